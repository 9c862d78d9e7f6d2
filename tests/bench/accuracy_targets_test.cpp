// Issue 13's accuracy targets (bench/accuracy_targets.h): a figure at its limit meets it,
// one just above misses it, and each miss names its figure.
#include "bench/accuracy_targets.h"

#include <gtest/gtest.h>

#include <cmath>

namespace opal::bench {
namespace {

ImageAccuracy atTheLimits() {
    ImageAccuracy a;
    a.relativeRmse = 0.01;
    a.luminance = {0.02, 0.03};
    a.chromaticity = {0.001, 0.005};
    a.negativeFraction = 0.0;
    return a;
}

TEST(AccuracyTargets, FiguresAtTheirLimitsPass) { EXPECT_TRUE(missedTargets(atTheLimits(), {}).empty()); }

TEST(AccuracyTargets, EachFigureAboveItsLimitIsNamed) {
    ImageAccuracy a = atTheLimits();
    a.relativeRmse = 0.0101;
    ASSERT_EQ(missedTargets(a, {}).size(), 1u);
    EXPECT_EQ(missedTargets(a, {})[0].rfind("rel.RMSE", 0), 0u);

    a = atTheLimits();
    a.luminance.p95 = 0.031;
    ASSERT_EQ(missedTargets(a, {}).size(), 1u);
    EXPECT_EQ(missedTargets(a, {})[0].rfind("Y p95", 0), 0u);

    a = atTheLimits();
    a.chromaticity.p95 = 0.0051;
    ASSERT_EQ(missedTargets(a, {}).size(), 1u);
    EXPECT_EQ(missedTargets(a, {})[0].rfind("chr p95", 0), 0u);

    a = atTheLimits();
    a.negativeFraction = 1.0 / 100000.0;  // one negative pixel is one too many
    ASSERT_EQ(missedTargets(a, {}).size(), 1u);
    EXPECT_EQ(missedTargets(a, {})[0].rfind("negative", 0), 0u);
}

TEST(AccuracyTargets, MedianAndDarkerHalfAreReportedNotJudged) {
    ImageAccuracy a = atTheLimits();
    a.luminance.median = 0.5;
    a.darkerHalf = {0.5, 0.9};
    EXPECT_TRUE(missedTargets(a, {}).empty());
}

TEST(AccuracyTargets, NotANumberMisses) {
    ImageAccuracy a = atTheLimits();
    a.relativeRmse = std::nan("");
    EXPECT_EQ(missedTargets(a, {}).size(), 1u);
}

TEST(AccuracyTargets, EveryTargetMissedAtOnce) {
    ImageAccuracy a;
    a.relativeRmse = 0.2, a.luminance.p95 = 0.2, a.chromaticity.p95 = 0.2, a.negativeFraction = 0.1;
    EXPECT_EQ(missedTargets(a, {}).size(), 4u);
    EXPECT_TRUE(missedTargets(a, {0.5, 0.5, 0.5, 0.5}).empty());  // looser targets
}

}  // namespace
}  // namespace opal::bench
