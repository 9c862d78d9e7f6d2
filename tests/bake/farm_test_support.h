// What the farm tests (tests/bake/opal_bake_farm_test.cpp, tests/farm/) share: the small
// bake they run, opal-bake as a child process, and the plain bake whose bytes a farm
// bake must reproduce.
#pragma once

#include "tests/bake/bake_test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

#include <string>
#include <vector>

#ifndef OPAL_BAKE_EXE
#error "tests/CMakeLists.txt must define OPAL_BAKE_EXE for the farm tests"
#endif

namespace opal::test {

// The shipped defaults but for the sample count: 4 charts of 16 x 16, so step 2 runs
// across several charts and the shards cut through them.
inline const std::vector<std::string> kFarmOptions = {"builtin:candle", "--samples", "1024", "--quiet"};

inline RunResult bakeWith(std::vector<std::string> args, const std::vector<std::string>& environment = {}) {
    args.insert(args.begin(), OPAL_BAKE_EXE);
    RunResult r = run(args, std::chrono::seconds(180), environment);
    EXPECT_FALSE(r.timedOut) << joined(args) << "\nstderr:\n" << r.err;
    return r;
}

// The plain bake of kFarmOptions into dir/candle, its JSON report in dir/plain.json.
struct PlainBake {
    ScratchDir dir;
    std::string sidecar;
    PlainBake() {
        const RunResult r =
            bakeWith(with(kFarmOptions, {"-o", (dir / "candle").string(), "--json", (dir / "plain.json").string()}));
        EXPECT_EQ(r.exitCode, 0) << r.err;
        sidecar = sidecarNamedBy(dir / "candle.usda");
    }
};

// `farm` holds exactly the plain bake's two files (no STEM.farm left), byte for byte.
inline void expectSameAsset(const PlainBake& plain, const ScratchDir& farm, const std::string& what) {
    EXPECT_EQ(farm.list(), (std::vector<std::string>{plain.sidecar, "candle.usda"})) << what;
    for (const std::string& file : {std::string("candle.usda"), plain.sidecar})
        EXPECT_TRUE(readBytes(farm / file) == readBytes(plain.dir / file))
            << what << ": " << file << " differs from the plain bake's";
}

inline nlohmann::json readJson(const std::filesystem::path& file) {
    std::ifstream in(file);
    return nlohmann::json::parse(in, nullptr, false);
}

// A farm bake's --json report: the plain bake's figures (what the asset is), and every
// stage's tasks measured (time and peak memory), the report's peak the largest task's.
inline void expectFarmReport(const PlainBake& plain, const std::filesystem::path& report, int shards) {
    const nlohmann::json p = readJson(plain.dir / "plain.json"), f = readJson(report);
    ASSERT_TRUE(f.is_object()) << report << " is not a JSON report";
    for (const char* key : {"samples", "charts", "grid", "subdivision_level", "render_vertices", "raw_bytes",
                            "step1_bytes", "step1_per_row", "step2_bytes", "sidecar_bytes", "energy_kept",
                            "transfer_rel_rmse", "options"})
        EXPECT_EQ(f[key], p[key]) << key;
    EXPECT_EQ(std::filesystem::path(f["sidecar_file"].get<std::string>()).filename(), plain.sidecar);
    const nlohmann::json& stages = f["farm"]["stages"];
    ASSERT_EQ(f["farm"]["shards"], shards);
    ASSERT_EQ(stages.size(), 5u);
    const std::vector<std::pair<std::string, int>> expected = {
        {"prepare", 1}, {"rows", shards}, {"columns", shards}, {"keep", shards}, {"merge", 1}};
    std::uint64_t largest = 0;
    for (std::size_t i = 0; i < stages.size(); ++i) {
        EXPECT_EQ(stages[i]["stage"], expected[i].first);
        EXPECT_EQ(stages[i]["tasks"], expected[i].second) << expected[i].first;
        EXPECT_EQ(stages[i]["measured"], expected[i].second) << expected[i].first;
        EXPECT_GT(stages[i]["seconds_max"].get<double>(), 0.0) << expected[i].first;
        EXPECT_GE(stages[i]["seconds_total"].get<double>(), stages[i]["seconds_max"].get<double>());
        EXPECT_GT(stages[i]["peak_rss_bytes"].get<std::uint64_t>(), 1u << 20) << expected[i].first;
        largest = std::max(largest, stages[i]["peak_rss_bytes"].get<std::uint64_t>());
    }
    EXPECT_EQ(f["peak_rss_bytes"].get<std::uint64_t>(), largest);
}

}  // namespace opal::test
