// What the farm tests (tests/bake/opal_bake_farm_test.cpp, tests/farm/) share: the small
// bake they run, opal-bake as a child process, and the plain bake whose bytes a farm
// bake must reproduce.
#pragma once

#include "tests/bake/bake_test_support.h"

#include <gtest/gtest.h>

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

// The plain bake of kFarmOptions into dir/candle.
struct PlainBake {
    ScratchDir dir;
    std::string sidecar;
    PlainBake() {
        const RunResult r = bakeWith(with(kFarmOptions, {"-o", (dir / "candle").string()}));
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

}  // namespace opal::test
