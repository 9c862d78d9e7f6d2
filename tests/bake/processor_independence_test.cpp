// A bake's bytes do not depend on the processor that runs it (bake/tool/baseline_math.h,
// raytrace/embree_device_config.h), so a farm of mixed CPUs writes one asset: builtin:candle
// baked with everything held to the baseline x86-64 instruction set (glibc's CPU features
// turned off down to x86-64 level 1 by GLIBC_TUNABLES, Embree's kernels capped at SSE2 by
// OPAL_EMBREE_ISA), and baked on one CPU (TBB's threads), is byte-identical to the default
// bake on this machine, whatever it has.
#include "bake/tool/baseline_math.h"
#include "raytrace/embree_device_config.h"
#include "schema/error.h"
#include "tests/bake/farm_test_support.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace opal {
namespace {

using test::PlainBake;
using test::ScratchDir;
using test::with;

// x86-64 level 1: every feature of levels 2 to 4 glibc's cpu-tunables accept turned off.
const std::string kBaselineTunables =
    "GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX,-AVX2,-FMA,-FMA4,-AVX512F,-SSE4_1,-SSE4_2,-SSSE3,-POPCNT,-LZCNT,-MOVBE,"
    "-BMI1,-BMI2";

TEST(ProcessorIndependence, TheTunablesPutGlibcAtTheBaselineInstructionSet) {
    // glibc ignores a feature name it does not know: its dynamic loader's own account of
    // the process shows that every name took (no x86-64-v2, v3 or v4 library folders).
    ASSERT_EQ(std::getenv("GLIBC_TUNABLES"), nullptr) << "the test sets GLIBC_TUNABLES itself";
    const test::RunResult r = test::run({"/lib64/ld-linux-x86-64.so.2", "--list-diagnostics"}, std::chrono::seconds(30),
                                        {kBaselineTunables});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("\ndl_hwcaps_subdirs_active=0x0\n"), std::string::npos) << r.out.substr(0, 400);
}

TEST(ProcessorIndependence, BaselineAndOneCpuBakesAreByteIdenticalToTheDefaultBake) {
    ASSERT_EQ(std::getenv("GLIBC_TUNABLES"), nullptr) << "the test sets GLIBC_TUNABLES itself";
    const PlainBake plain;  // this machine's processor, every CPU
    const ScratchDir baseline;
    const test::RunResult forced = test::bakeWith(with(test::kFarmOptions, {"-o", (baseline / "candle").string()}),
                                                  {kBaselineTunables, std::string(kEmbreeIsaVariable) + "=sse2"});
    ASSERT_EQ(forced.exitCode, 0) << forced.err;
    test::expectSameAsset(plain, baseline, "baseline x86-64 (glibc and Embree)");

    const ScratchDir oneCpu;
    std::vector<std::string> args = with({"/usr/bin/taskset", "-c", "0", OPAL_BAKE_EXE}, test::kFarmOptions);
    args = with(args, {"-o", (oneCpu / "candle").string()});
    const test::RunResult single = test::run(args, std::chrono::seconds(180));
    ASSERT_EQ(single.exitCode, 0) << single.err;
    test::expectSameAsset(plain, oneCpu, "one CPU");
}

TEST(ProcessorIndependence, AnUnknownEmbreeIsaFailsTheBakeNamingTheVariable) {
    const ScratchDir dir;
    const test::RunResult r = test::bakeWith(with(test::kFarmOptions, {"-o", (dir / "candle").string()}),
                                             {std::string(kEmbreeIsaVariable) + "=avx3"});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("OPAL_EMBREE_ISA = 'avx3': not an instruction set Embree knows"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "candle.usda"));
}

TEST(ProcessorIndependence, TheBaselineMathSettingJoinsTheUsersTunables) {
    EXPECT_EQ(withBaselineMath(""), "glibc.cpu.hwcaps=-AVX,-AVX2,-FMA,-FMA4");
    EXPECT_EQ(withBaselineMath("glibc.malloc.check=3"), "glibc.malloc.check=3:glibc.cpu.hwcaps=-AVX,-AVX2,-FMA,-FMA4");
    // glibc keeps one hwcaps entry: the user's features stay off too.
    EXPECT_EQ(withBaselineMath("glibc.cpu.hwcaps=-AVX512F:glibc.malloc.check=3"),
              "glibc.cpu.hwcaps=-AVX512F,-AVX,-AVX2,-FMA,-FMA4:glibc.malloc.check=3");
    EXPECT_EQ(withBaselineMath("glibc.cpu.hwcaps="), "glibc.cpu.hwcaps=-AVX,-AVX2,-FMA,-FMA4");
}

}  // namespace
}  // namespace opal
