// An asset is replaced as one unit, by the real opal-bake: killed at every write step
// (OPAL_CRASH_AT, schema/usd/crash_point.h) and at random moments (SIGKILL), the stem
// holds the complete previous asset or the complete new one, byte for byte, and the next
// bake removes what the killed one left; a re-bake of the same mesh with another material
// is never mixed with the previous one; a second bake of a stem fails while the first runs.
#include "schema/asset/asset_layer.h"
#include "schema/asset/bake_id.h"
#include "tests/bake/bake_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <thread>

#ifndef OPAL_BAKE_EXE
#error "tests/CMakeLists.txt must define OPAL_BAKE_EXE for opal-test-bake"
#endif

namespace opal {
namespace {

using namespace std::chrono_literals;
using test::ScratchDir;

// Two bakes of the same mesh that differ only in the default material: their halves pass
// every check but the bake identifier's.
const std::vector<std::string> kSmall = {"builtin:candle", "--samples", "256",  "--level", "0",
                                         "--env-res",      "8",         "--env-terms", "16", "-q"};

std::vector<std::string> bakeArgs(const std::filesystem::path& stem, const std::string& material) {
    std::vector<std::string> args = {OPAL_BAKE_EXE};
    args.insert(args.end(), kSmall.begin(), kSmall.end());
    args.insert(args.end(), {"--material", material, "-o", stem.string()});
    return args;
}

test::RunResult bake(const std::filesystem::path& stem, const std::string& material,
                     const std::vector<std::string>& environment = {}) {
    const test::RunResult r = test::run(bakeArgs(stem, material), 120s, environment);
    EXPECT_FALSE(r.timedOut) << r.err;
    return r;
}

// What a complete asset is: the layer's bytes and those of the sidecar it names.
struct AssetFiles {
    std::string sidecarName, layer, sidecar;
    std::uint64_t id = 0;
};

AssetFiles bakeReference(const std::filesystem::path& stem, const std::string& material) {
    const test::RunResult r = bake(stem, material);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    AssetFiles a;
    a.sidecarName = test::sidecarNamedBy(stem.string() + ".usda");
    a.layer = test::readBytes(stem.string() + ".usda");
    a.sidecar = test::readBytes(stem.parent_path() / a.sidecarName);
    a.id = readAsset(stem.string() + ".usda").bake.identifier.value_or(0);
    return a;
}

// Which of the two complete assets the stem holds: 0 or 1, or -1 (with a test failure)
// when it holds neither.
int whichAsset(const std::filesystem::path& stem, const AssetFiles (&assets)[2], const std::string& context) {
    const std::filesystem::path usda = stem.string() + ".usda";
    TranslucentAsset asset;
    try {
        asset = readAsset(usda);
    } catch (const std::exception& e) {
        ADD_FAILURE() << context << ": the stem holds no readable asset: " << e.what();
        return -1;
    }
    const std::string layer = test::readBytes(usda), sidecarName = test::sidecarNamedBy(usda);
    for (int i = 0; i < 2; ++i)
        if (layer == assets[i].layer) {
            EXPECT_EQ(sidecarName, assets[i].sidecarName) << context;
            EXPECT_TRUE(test::readBytes(stem.parent_path() / sidecarName) == assets[i].sidecar)
                << context << ": the sidecar is not the one its layer was baked with";
            EXPECT_EQ(asset.bake.identifier, assets[i].id) << context;
            return i;
        }
    ADD_FAILURE() << context << ": the layer is neither the previous nor the new one";
    return -1;
}

// After a completed bake the stem holds exactly its layer and its sidecar.
void expectOnlyTheAsset(const ScratchDir& dir, const AssetFiles& asset, const std::string& context) {
    EXPECT_EQ(dir.list(), (std::vector<std::string>{asset.sidecarName, "candle.usda"})) << context;
}

const char* const kMaterials[2] = {"marble", "skin1"};

TEST(AssetCommit, AReBakeWithAnotherMaterialIsNeverMixedWithThePreviousBake) {
    const ScratchDir one, two;
    const AssetFiles marble = bakeReference(one / "candle", "marble");
    const AssetFiles skin = bakeReference(two / "candle", "skin1");
    ASSERT_NE(marble.id, skin.id);
    ASSERT_NE(marble.sidecarName, skin.sidecarName) << "each bake's sidecar has a name of its own";
    // The mix a kill between two renames used to leave: the marble layer with the skin1
    // sidecar in its place. Same mesh, name, units and K: only the identifier differs.
    test::writeText(one / marble.sidecarName, skin.sidecar);
    try {
        readAsset(one / "candle.usda");
        FAIL() << "a mixed pair loaded";
    } catch (const std::exception& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("sidecar and layer are not from the same bake"), std::string::npos) << message;
        EXPECT_NE(message.find(formatBakeId(marble.id)), std::string::npos) << message;
        EXPECT_NE(message.find(formatBakeId(skin.id)), std::string::npos) << message;
    }
}

TEST(AssetCommit, KilledAtEveryWriteStepTheStemHoldsThePreviousOrTheNewAsset) {
    const ScratchDir reference0, reference1, dir;
    const AssetFiles assets[2] = {bakeReference(reference0 / "candle", kMaterials[0]),
                                  bakeReference(reference1 / "candle", kMaterials[1])};
    ASSERT_EQ(bake(dir / "candle", kMaterials[0]).exitCode, 0);
    // Each point, and which asset the stem must hold when the bake dies there.
    const std::pair<const char*, bool> points[] = {
        {"bake:writing", false},  {"bake:cleaned", false},  {"opal:created", false}, {"opal:written", false},
        {"opal:renamed", false},  {"usda:created", false},  {"usda:written", false}, {"usda:renamed", true},
        {"bake:committed", true}, {"bake:pruned-one", true}, {"bake:pruned", true}};
    int current = 0, kills = 0, outcomes[2] = {0, 0};
    for (const auto& [point, committed] : points) {
        const int next = 1 - current;
        const std::string context = std::string("killed at ") + point;
        const test::RunResult killed =
            bake(dir / "candle", kMaterials[next], {std::string("OPAL_CRASH_AT=") + point});
        EXPECT_EQ(killed.termSignal, SIGKILL) << context << " (exit " << killed.exitCode << ")\n" << killed.err;
        kills += killed.termSignal == SIGKILL;
        const int held = whichAsset(dir / "candle", assets, context);
        EXPECT_EQ(held, committed ? next : current) << context;
        if (held >= 0) ++outcomes[held == next];
        // The next bake (towards the same asset) removes what the killed one left.
        const test::RunResult after = bake(dir / "candle", kMaterials[next]);
        ASSERT_EQ(after.exitCode, 0) << context << ": " << after.err;
        EXPECT_EQ(whichAsset(dir / "candle", assets, context + ", then baked again"), next);
        expectOnlyTheAsset(dir, assets[next], context + ", then baked again");
        current = next;
    }
    EXPECT_EQ(kills, int(std::size(points)));
    std::printf("[ crash points ] %d kills: %d left the previous asset, %d the new one\n", kills, outcomes[0],
                outcomes[1]);
}

TEST(AssetCommit, KilledAtRandomMomentsTheStemHoldsThePreviousOrTheNewAsset) {
    const ScratchDir reference0, reference1, dir;
    const AssetFiles assets[2] = {bakeReference(reference0 / "candle", kMaterials[0]),
                                  bakeReference(reference1 / "candle", kMaterials[1])};
    const auto start = std::chrono::steady_clock::now();
    ASSERT_EQ(bake(dir / "candle", kMaterials[0]).exitCode, 0);
    const auto duration = std::chrono::steady_clock::now() - start;
    // OPAL_KILL_RUNS raises the count for a longer run on demand.
    const char* runs = std::getenv("OPAL_KILL_RUNS");
    const int rounds = runs ? std::max(1, std::atoi(runs)) : 12;
    std::mt19937 random(20261125);
    std::uniform_real_distribution<double> moment(0.0, 1.1);  // some land after the bake ended
    int current = 0, kills = 0, finished = 0, outcomes[2] = {0, 0};
    for (int round = 0; round < rounds; ++round) {
        const int next = 1 - current;
        const auto delay = std::chrono::duration_cast<std::chrono::microseconds>(duration * moment(random));
        test::ChildProcess child(bakeArgs(dir / "candle", kMaterials[next]));
        std::this_thread::sleep_for(delay);
        child.signal(SIGKILL);
        ASSERT_TRUE(child.wait(60s));
        const bool wasKilled = child.termSignal() == SIGKILL;
        kills += wasKilled;
        finished += !wasKilled;
        if (!wasKilled) {
            EXPECT_EQ(child.exitCode(), 0) << child.err();
        }
        const std::string context = "round " + std::to_string(round) + " (signal after " +
                                    std::to_string(delay.count()) + " us)";
        const int held = whichAsset(dir / "candle", assets, context);
        if (held < 0) continue;
        if (wasKilled) {
            ++outcomes[held == next];
        } else {
            EXPECT_EQ(held, next) << context;
        }
        current = held;
    }
    // Whatever the kills left, one complete bake leaves exactly the asset's two files.
    const int next = 1 - current;
    ASSERT_EQ(bake(dir / "candle", kMaterials[next]).exitCode, 0);
    EXPECT_EQ(whichAsset(dir / "candle", assets, "after the kills"), next);
    expectOnlyTheAsset(dir, assets[next], "after the kills");
    std::printf("[ random kills ] %d rounds: %d killed (%d left the previous asset, %d the new one), %d finished\n",
                rounds, kills, outcomes[0], outcomes[1], finished);
}

TEST(AssetCommit, ASecondBakeOfTheSameStemFailsWhileTheFirstRuns) {
    const ScratchDir dir;
    // The first bake is stopped (SIGSTOP) once it is working, so that it holds the stem for
    // as long as the second takes, however fast or slow the machine.
    std::vector<std::string> args = bakeArgs(dir / "candle", "marble");
    args.erase(std::find(args.begin(), args.end(), "-q"));
    test::ChildProcess first(args);
    ASSERT_TRUE(first.waitForStderr("opal-bake: subdivide", 60s)) << first.err();
    first.signal(SIGSTOP);
    const test::RunResult second = bake(dir / "candle", "skin1");
    first.signal(SIGCONT);
    EXPECT_EQ(second.exitCode, 1) << second.err;
    EXPECT_NE(second.err.find((dir / "candle.lock").string()), std::string::npos) << second.err;
    EXPECT_NE(second.err.find("another opal-bake (pid " + std::to_string(first.pid()) + ")"), std::string::npos)
        << second.err;
    ASSERT_TRUE(first.wait(120s));
    EXPECT_EQ(first.exitCode(), 0) << first.err();
    const TranslucentAsset asset = readAsset(dir / "candle.usda");
    const double marble = findPreset("marble")->sigmaA[0], skin = findPreset("skin1")->sigmaA[0];
    ASSERT_GT(std::abs(marble - skin), 1e-3 * marble);
    EXPECT_NEAR(asset.defaultMaterial.sigmaA[0], marble, 1e-6 * marble) << "the first bake's asset";
    EXPECT_EQ(dir.list(), (std::vector<std::string>{test::sidecarNamedBy(dir / "candle.usda"), "candle.usda"}));
}

}  // namespace
}  // namespace opal
