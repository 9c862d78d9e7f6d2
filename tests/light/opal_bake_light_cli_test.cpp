// `opal-bake light` as a pipeline sees it: exit codes and messages for bad specs and
// arguments, the files a bake writes (layer naming its sidecar, the sidecar readable),
// the JSON report, and byte-identical repeat bakes. Every run is a real child process.
#include "schema/asset/bake_id.h"
#include "schema/asset/shadow_field_file.h"
#include "schema/usd/usda_reader.h"
#include "tests/bake/bake_test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <csignal>
#include <fstream>

#ifndef OPAL_BAKE_EXE
#error "tests/CMakeLists.txt must define OPAL_BAKE_EXE for opal-test-light"
#endif

namespace opal {
namespace {

using namespace std::chrono_literals;
using test::ScratchDir;

const std::vector<std::string> kSmall = {"--shells", "3", "--directions", "2", "--map-size", "8", "--rays", "2"};

test::RunResult bakeLight(std::vector<std::string> args, const std::vector<std::string>& environment = {}) {
    args.insert(args.begin(), {OPAL_BAKE_EXE, "light"});
    test::RunResult r = test::run(args, 120s, environment);
    EXPECT_FALSE(r.timedOut) << test::joined(args) << "\nstderr:\n" << r.err;
    return r;
}

std::string fieldNamedBy(const std::filesystem::path& usda) {
    const std::string text = test::readBytes(usda);
    const std::string key = "uniform asset opal:field = @./";
    const std::size_t start = text.find(key);
    if (start == std::string::npos) return "";
    const std::size_t end = text.find('@', start + key.size());
    return text.substr(start + key.size(), end - start - key.size());
}

TEST(OpalBakeLightCli, BadSpecsExitTwoNamingTheProblem) {
    const ScratchDir dir;
    const struct {
        const char* spec;
        const char* message;
    } cases[] = {
        {"candle:radius=3", "unknown kind 'candle'"},
        {"sphere:radius=-3", "radius=-3 must be positive"},
        {"flame:height=20", "missing radius="},
        {"mesh:file=missing.obj", "missing.obj"},
    };
    for (const auto& c : cases) {
        const test::RunResult r = bakeLight({c.spec, "-o", (dir / "light").string()});
        EXPECT_EQ(r.exitCode, 2) << c.spec;
        EXPECT_NE(r.err.find("opal-bake light: light spec '" + std::string(c.spec) + "'"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    }
    EXPECT_TRUE(dir.list().empty());
}

TEST(OpalBakeLightCli, BadArgumentsExitTwo) {
    const ScratchDir dir;
    EXPECT_EQ(bakeLight({"sphere:radius=3"}).exitCode, 2);  // no -o
    EXPECT_EQ(bakeLight({"-o", (dir / "x").string()}).exitCode, 2);  // no spec
    EXPECT_EQ(bakeLight({"sphere:radius=3", "-o", (dir / "x").string(), "--shells", "1"}).exitCode, 2);
    EXPECT_EQ(bakeLight({"sphere:radius=3", "-o", (dir / "x").string(), "--map-size", "12"}).exitCode, 2);
    EXPECT_TRUE(dir.list().empty());
}

TEST(OpalBakeLightCli, WritesLayerSidecarAndReportAndRepeatsByteForByte) {
    const ScratchDir one, two;
    std::vector<std::string> args = {"lamp:radius=2,height=4", "-o", (one / "lamp").string(), "--json",
                                     (one / "report.json").string(), "--quiet"};
    args.insert(args.end(), kSmall.begin(), kSmall.end());
    const test::RunResult a = bakeLight(args);
    ASSERT_EQ(a.exitCode, 0) << a.err;
    EXPECT_EQ(a.err, "");  // --quiet
    const std::string sidecar = fieldNamedBy(one / "lamp.usda");
    ASSERT_FALSE(sidecar.empty()) << test::readBytes(one / "lamp.usda");
    EXPECT_EQ(one.list(), (std::vector<std::string>{sidecar, "lamp.usda", "report.json"}));

    const usda::Layer layer = usda::readUsdaFile(one / "lamp.usda");
    ASSERT_EQ(layer.rootPrims.size(), 1u);
    EXPECT_EQ(layer.rootPrims[0].typeName, "OpalShadowFieldLight");
    const ShadowField field = readShadowFieldFile(one / sidecar);
    EXPECT_EQ(field.shells(), 3u);
    EXPECT_EQ(field.directionFaceSize, 2u);
    EXPECT_EQ(field.mapFaceSize, 8u);
    EXPECT_EQ(field.name, "lamp");
    ASSERT_TRUE(field.bakeId);
    EXPECT_NE(sidecar.find(formatBakeId(*field.bakeId)), std::string::npos);

    const nlohmann::json report = nlohmann::json::parse(test::readBytes(one / "report.json"));
    EXPECT_EQ(report["sizes"]["sidecarBytes"].get<std::uint64_t>(), std::filesystem::file_size(one / sidecar));
    EXPECT_EQ(report["field"]["maps"].get<std::uint64_t>(), 3u * 6 * 2 * 2);
    EXPECT_GT(report["time"]["bakeSeconds"].get<double>(), 0.0);
    EXPECT_GT(report["compression"]["worstMapRelativeError"].get<double>(), 0.0);
    EXPECT_LE(report["compression"]["worstMapRelativeError"].get<double>(), 0.011);

    args[2] = (two / "lamp").string();
    args[4] = (two / "report.json").string();
    ASSERT_EQ(bakeLight(args).exitCode, 0);
    EXPECT_EQ(fieldNamedBy(two / "lamp.usda"), sidecar);
    EXPECT_EQ(test::readBytes(one / sidecar), test::readBytes(two / sidecar));
    EXPECT_EQ(test::readBytes(one / "lamp.usda"), test::readBytes(two / "lamp.usda"));
}

TEST(OpalBakeLightCli, ARebakeReplacesTheSidecar) {
    const ScratchDir dir;
    std::vector<std::string> args = {"sphere:radius=1", "-o", (dir / "s").string(), "--quiet"};
    args.insert(args.end(), kSmall.begin(), kSmall.end());
    ASSERT_EQ(bakeLight(args).exitCode, 0);
    const std::string first = fieldNamedBy(dir / "s.usda");
    args[0] = "sphere:radius=2";
    ASSERT_EQ(bakeLight(args).exitCode, 0);
    const std::string second = fieldNamedBy(dir / "s.usda");
    EXPECT_NE(first, second);
    EXPECT_EQ(dir.list(), (std::vector<std::string>{second, "s.usda"}));
}

// A bake killed between writing its sidecar and committing its layer leaves the previous
// light intact (and a stray sidecar or temporary file that the next bake removes).
TEST(OpalBakeLightCli, AKilledBakeLeavesThePreviousLight) {
    const ScratchDir dir;
    std::vector<std::string> args = {"sphere:radius=1", "-o", (dir / "s").string(), "--quiet"};
    args.insert(args.end(), kSmall.begin(), kSmall.end());
    ASSERT_EQ(bakeLight(args).exitCode, 0);
    const std::string first = fieldNamedBy(dir / "s.usda");
    const std::string layer = test::readBytes(dir / "s.usda");
    args[0] = "sphere:radius=2";
    for (const char* point : {"opal:written", "bake:cleaned", "usda:written"}) {
        const test::RunResult killed = bakeLight(args, {std::string("OPAL_CRASH_AT=") + point});
        EXPECT_EQ(killed.termSignal, SIGKILL) << point << "\n" << killed.err;
        EXPECT_EQ(test::readBytes(dir / "s.usda"), layer) << point;
        EXPECT_NO_THROW(readShadowFieldFile(dir / first)) << point;
    }
    ASSERT_EQ(bakeLight(args).exitCode, 0);
    const std::string second = fieldNamedBy(dir / "s.usda");
    EXPECT_NE(second, first);
    EXPECT_EQ(dir.list(), (std::vector<std::string>{second, "s.usda"}));
}

TEST(OpalBakeLightCli, InterruptedBakeWritesNothing) {
    const ScratchDir dir;
    test::ChildProcess child({OPAL_BAKE_EXE, "light", "sphere:radius=5", "-o", (dir / "s").string()});
    ASSERT_TRUE(child.waitForStderr("opal-bake: light field", 60s)) << child.err();
    child.signal(SIGINT);
    ASSERT_TRUE(child.wait(60s)) << "no exit within 60 s of the signal";
    EXPECT_EQ(child.exitCode(), 130) << child.err();
    EXPECT_NE(child.err().find("interrupted; nothing was written"), std::string::npos) << child.err();
    EXPECT_TRUE(dir.list().empty());
}

}  // namespace
}  // namespace opal
