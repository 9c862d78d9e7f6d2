// opal-bake batch (bake/tool/batch_command.h) as a pipeline runs it: a manifest of three
// assets, one of which cannot be baked; the failure is retried once, reported first and
// fails the run; a second run skips the unchanged assets without touching them; changing
// an asset's arguments bakes it again; a bad manifest names the entry. With --farm local the
// same, each asset baked as farm tasks to the plain batch's bytes.
#include "tests/bake/bake_test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

#ifndef OPAL_BAKE_EXE
#error "tests/CMakeLists.txt must define OPAL_BAKE_EXE for opal-test-bake"
#endif

namespace opal {
namespace {

using namespace std::chrono_literals;
using test::ScratchDir;

std::string manifest(const std::string& wickSamples) {
    return R"({"assets": [
  {"input": "builtin:wick", "output": "out/wick", "args": ["--samples", ")" + wickSamples + R"("]},
  {"input": "missing.obj", "output": "out/missing"},
  {"input": "builtin:candle", "output": "out/candle",
   "args": ["--samples", "256", "--level", "1", "--env-res", "8", "--env-terms", "32"]}
]})";
}

// `extra`: options after the manifest (--farm local, ...); `environment`: for every bake.
test::RunResult batch(const ScratchDir& dir, const std::vector<std::string>& extra = {},
                      const std::vector<std::string>& environment = {}) {
    std::vector<std::string> args = {OPAL_BAKE_EXE, "batch", (dir / "batch.json").string(), "--json",
                                     (dir / "report.json").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return test::run(args, 300s, environment);
}

std::vector<std::string> statuses(const ScratchDir& dir) {
    const nlohmann::json report = nlohmann::json::parse(test::readBytes(dir / "report.json"));
    std::vector<std::string> s;
    for (const auto& asset : report["assets"]) s.push_back(asset["status"].get<std::string>());
    return s;
}

TEST(OpalBakeBatch, BakesSkipsUnchangedRetriesAndReportsFailuresFirst) {
    const ScratchDir dir;
    test::writeText(dir / "batch.json", manifest("256"));
    const test::RunResult first = batch(dir);
    EXPECT_EQ(first.exitCode, 1) << first.err;
    EXPECT_EQ(statuses(dir), (std::vector<std::string>{"baked", "failed", "baked"}));
    const nlohmann::json report = nlohmann::json::parse(test::readBytes(dir / "report.json"));
    EXPECT_EQ(report["failed"], 1);
    EXPECT_EQ(report["assets"][1]["attempts"], 2);
    EXPECT_NE(report["assets"][1]["error"].get<std::string>().find("missing.obj"), std::string::npos);
    // The table lists the failure first, with its error.
    const std::size_t failed = first.out.find("failed"), baked = first.out.find("baked");
    ASSERT_NE(failed, std::string::npos) << first.out;
    EXPECT_LT(failed, baked) << first.out;
    EXPECT_TRUE(std::filesystem::exists(dir / "out/wick.usda"));
    EXPECT_TRUE(std::filesystem::exists(dir / "out/candle.usda"));

    const std::string wickLayer = test::readBytes(dir / "out/wick.usda");
    const auto wickTime = std::filesystem::last_write_time(dir / "out/wick.usda");
    const test::RunResult second = batch(dir);
    EXPECT_EQ(second.exitCode, 1);
    EXPECT_EQ(statuses(dir), (std::vector<std::string>{"skipped", "failed", "skipped"}));
    EXPECT_EQ(std::filesystem::last_write_time(dir / "out/wick.usda"), wickTime);  // not rewritten

    test::writeText(dir / "batch.json", manifest("512"));
    const test::RunResult third = batch(dir);
    EXPECT_EQ(third.exitCode, 1);
    EXPECT_EQ(statuses(dir), (std::vector<std::string>{"baked", "failed", "skipped"}));
    EXPECT_NE(test::readBytes(dir / "out/wick.usda"), wickLayer);
}

TEST(OpalBakeBatch, OnTheLocalFarmItBakesThePlainBatchsBytesSkipsRetriesAndReportsFailuresFirst) {
    const ScratchDir plain, farm;
    test::writeText(plain / "batch.json", manifest("256"));
    test::writeText(farm / "batch.json", manifest("256"));
    ASSERT_EQ(batch(plain).exitCode, 1);
    const test::RunResult first = batch(farm, {"--farm", "local", "--shards", "2"});
    EXPECT_EQ(first.exitCode, 1) << first.err;
    EXPECT_EQ(statuses(farm), (std::vector<std::string>{"baked", "failed", "baked"}));
    const nlohmann::json report = nlohmann::json::parse(test::readBytes(farm / "report.json"));
    EXPECT_EQ(report["failed"], 1);
    EXPECT_EQ(report["assets"][1]["attempts"], 2);
    EXPECT_NE(report["assets"][1]["error"].get<std::string>().find("missing.obj: no such input file"), std::string::npos)
        << report.dump(2);
    EXPECT_LT(first.out.find("failed"), first.out.find("baked")) << first.out;
    for (const char* stem : {"wick", "candle"}) {
        const std::string sidecar = test::sidecarNamedBy(farm / "out" / (std::string(stem) + ".usda"));
        EXPECT_EQ(sidecar, test::sidecarNamedBy(plain / "out" / (std::string(stem) + ".usda"))) << stem;
        for (const std::string& file : {std::string(stem) + ".usda", sidecar})
            EXPECT_TRUE(test::readBytes(farm / "out" / file) == test::readBytes(plain / "out" / file))
                << file << ": the farm batch's differs from the plain batch's";
        EXPECT_FALSE(std::filesystem::exists(farm / "out" / (std::string(stem) + ".farm"))) << stem;
    }
    // The same bytes either way: neither a plain nor a farm batch bakes them again.
    const auto wickTime = std::filesystem::last_write_time(farm / "out/wick.usda");
    EXPECT_EQ(batch(farm).exitCode, 1);
    EXPECT_EQ(statuses(farm), (std::vector<std::string>{"skipped", "failed", "skipped"}));
    EXPECT_EQ(batch(farm, {"--farm", "local"}).exitCode, 1);
    EXPECT_EQ(statuses(farm), (std::vector<std::string>{"skipped", "failed", "skipped"}));
    EXPECT_EQ(std::filesystem::last_write_time(farm / "out/wick.usda"), wickTime);
}

TEST(OpalBakeBatch, AFarmTaskFailingEveryTimeFailsItsAssetAfterOneRetryNamingTheTask) {
    const ScratchDir dir;
    test::writeText(dir / "batch.json",
                    R"({"assets": [{"input": "builtin:wick", "output": "out/wick", "args": ["--samples", "256"]}]})");
    const test::RunResult r = batch(dir, {"--farm", "local", "--shards", "2"}, {"OPAL_CRASH_AT=farm:keep-1"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    const nlohmann::json report = nlohmann::json::parse(test::readBytes(dir / "report.json"));
    EXPECT_EQ(report["assets"][0]["status"], "failed");
    EXPECT_EQ(report["assets"][0]["attempts"], 2);
    EXPECT_NE(report["assets"][0]["error"].get<std::string>().find("farm task keep 1 failed twice"), std::string::npos)
        << report.dump(2);
    EXPECT_FALSE(std::filesystem::exists(dir / "out/wick.usda"));
    // Farm options belong to the batch, not to an asset, and Slurm's need --farm slurm.
    EXPECT_EQ(batch(dir, {"--shards", "2"}).exitCode, 2);
    EXPECT_EQ(batch(dir, {"--farm", "local", "--mem", "4G"}).exitCode, 2);
    test::writeText(dir / "batch.json",
                    R"({"assets": [{"input": "builtin:wick", "output": "out/wick", "args": ["--farm", "local"]}]})");
    EXPECT_NE(batch(dir).err.find("assets[0].args[0]: '--farm' is set by the batch"), std::string::npos);
}

TEST(OpalBakeBatch, ABadManifestNamesTheEntry) {
    const ScratchDir dir;
    test::writeText(dir / "batch.json", R"({"assets": [{"input": "builtin:wick", "output": "a"},
                                                        {"input": "builtin:wick", "args": ["-o", "b"]}]})");
    const test::RunResult r = batch(dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("batch.json: assets[1].output: missing"), std::string::npos) << r.err;
    test::writeText(dir / "batch.json", R"({"assets": [{"input": "builtin:wick", "output": "a", "args": ["-o", "b"]}]})");
    EXPECT_NE(batch(dir).err.find("assets[0].args[0]: '-o' is set by the batch"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(dir / "a.usda"));
}

}  // namespace
}  // namespace opal
