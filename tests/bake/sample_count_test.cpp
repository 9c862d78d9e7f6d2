#include "bake/sample_count.h"

#include "schema/error.h"

#include <gtest/gtest.h>

namespace opal {
namespace {

std::string errorOf(std::uint64_t samples) {
    try {
        chartLayoutForSampleCount(samples);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(SampleCount, SplitsIntoChartsOfUpTo64By64) {
    struct Case {
        std::uint64_t samples;
        std::uint32_t charts, log2Size;
    };
    for (Case c : {Case{16384, 4, 6}, Case{65536, 16, 6}, Case{262144, 64, 6}, Case{4096, 1, 6},
                   Case{12288, 3, 6}, Case{1024, 1, 5}, Case{3072, 3, 5}, Case{256, 1, 4}, Case{16, 1, 2},
                   Case{48, 3, 2}}) {
        ChartLayout layout = chartLayoutForSampleCount(c.samples);
        EXPECT_EQ(layout.charts, c.charts) << c.samples;
        EXPECT_EQ(layout.log2Size, c.log2Size) << c.samples;
        EXPECT_EQ(layout.cells(), c.samples);
    }
}

TEST(SampleCount, RejectsOtherCountsNamingNearbyValidOnes) {
    EXPECT_EQ(errorOf(65000),
              "sample count 65000 is not M x 4^n with charts of up to 64 x 64 (at least 16, at most 2147483648); "
              "nearby valid counts: 61440 (15 x 64 x 64), 65536 (16 x 64 x 64)");
    EXPECT_NE(errorOf(100).find("nearby valid counts: 64 (1 x 8 x 8), 128 (2 x 8 x 8)"), std::string::npos)
        << errorOf(100);
    EXPECT_NE(errorOf(5000).find("nearby valid counts: 4096 (1 x 64 x 64), 8192 (2 x 64 x 64)"), std::string::npos)
        << errorOf(5000);
    EXPECT_NE(errorOf(8).find("nearby valid counts: 16 (1 x 4 x 4)"), std::string::npos) << errorOf(8);
    EXPECT_NE(errorOf(0).find("sample count 0 "), std::string::npos);
}

}  // namespace
}  // namespace opal
