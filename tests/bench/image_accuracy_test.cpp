// The figures of `opal-bench accuracy` (bench/image_accuracy.h) on images whose errors are
// known by construction.
#include "bench/image_accuracy.h"

#include "schema/error.h"

#include <gtest/gtest.h>

#include <vector>

namespace opal::bench {
namespace {

TEST(ImageAccuracy, PercentilesAreNearestRank) {
    std::vector<double> v = {5, 1, 4, 2, 3};
    EXPECT_EQ(percentile(v, 0.5), 3.0);
    EXPECT_EQ(percentile(v, 0.95), 5.0);
    EXPECT_EQ(percentile(v, 0.0), 1.0);
    std::vector<double> hundred;
    for (int i = 1; i <= 100; ++i) hundred.push_back(i);
    EXPECT_EQ(percentile(hundred, 0.95), 95.0);
    EXPECT_EQ(percentile(hundred, 0.99), 99.0);
    std::vector<double> none;
    EXPECT_EQ(percentile(none, 0.5), 0.0);
}

TEST(ImageAccuracy, AUniformScaleIsItsOwnRelativeError) {
    // Grey pixels of rising brightness; the engine is 2% too bright everywhere.
    std::vector<float> reference, engine;
    for (int p = 0; p < 200; ++p)
        for (int c = 0; c < 3; ++c) {
            reference.push_back(0.01f * float(p + 1));
            engine.push_back(1.02f * 0.01f * float(p + 1));
        }
    const std::vector<std::uint8_t> mask(200, 1);
    const ImageAccuracy a = measureAccuracy(engine, reference, mask);
    EXPECT_EQ(a.pixels, 200u);
    EXPECT_EQ(a.measured, 199u);  // 1% of the 99th percentile (1.98) is 0.0198: 0.01 is below
    EXPECT_NEAR(a.relativeRmse, 0.02, 1e-6);
    EXPECT_NEAR(a.luminance.median, 0.02, 1e-5);
    EXPECT_NEAR(a.luminance.p95, 0.02, 1e-5);
    EXPECT_NEAR(a.darkerHalf.p95, 0.02, 1e-5);
    EXPECT_NEAR(a.chromaticity.p95, 0.0, 1e-6);  // same hue
    EXPECT_EQ(a.negativeFraction, 0.0);
}

TEST(ImageAccuracy, WithoutAMaskEveryPixelCounts) {
    std::vector<float> reference, engine;
    for (int p = 0; p < 50; ++p)
        for (int c = 0; c < 3; ++c) {
            reference.push_back(0.1f * float(p + 1 + c));
            engine.push_back(0.1f * float(p + 1 + c) * (p % 3 == 0 ? 1.05f : 0.99f));
        }
    const ImageAccuracy every = measureAccuracy(engine, reference);
    const ImageAccuracy masked = measureAccuracy(engine, reference, std::vector<std::uint8_t>(50, 1));
    EXPECT_EQ(every.pixels, 50u);
    EXPECT_EQ(every.relativeRmse, masked.relativeRmse);
    EXPECT_EQ(every.luminance.p95, masked.luminance.p95);
    EXPECT_NEAR(every.luminance.p95, 0.05, 1e-5);
}

TEST(ImageAccuracy, DimPixelsAndTheDarkerHalfAreSeparated) {
    // 100 bright pixels exact; 100 darker ones 10% off; 10 nearly black ones 100% off.
    std::vector<float> reference, engine;
    const auto add = [&](float value, float factor) {
        for (int c = 0; c < 3; ++c) {
            reference.push_back(value);
            engine.push_back(value * factor);
        }
    };
    for (int i = 0; i < 100; ++i) add(1.0f, 1.0f);
    for (int i = 0; i < 100; ++i) add(0.5f, 1.1f);
    for (int i = 0; i < 10; ++i) add(0.001f, 2.0f);
    const std::vector<std::uint8_t> mask(210, 1);
    const ImageAccuracy a = measureAccuracy(engine, reference, mask);
    EXPECT_EQ(a.measured, 200u);  // the black ones are below 1% of the 99th percentile
    EXPECT_NEAR(a.darkerHalf.median, 0.1, 1e-5);
    EXPECT_NEAR(a.darkerHalf.p95, 0.1, 1e-5);
    EXPECT_NEAR(a.luminance.p95, 0.1, 1e-5);
    EXPECT_EQ(a.luminance.median, 0.0);  // rank 100 of 200 sorted errors: the last exact one
}

TEST(ImageAccuracy, HueShiftsAndNegativePixelsAreCounted) {
    // Reference white; the engine moves 0.01 from blue to red on every other pixel, and one
    // pixel has a negative channel. Outside the mask nothing counts.
    std::vector<float> reference, engine;
    std::vector<std::uint8_t> mask;
    for (int p = 0; p < 100; ++p) {
        reference.insert(reference.end(), {0.3f, 0.3f, 0.3f});
        if (p % 2 == 0)
            engine.insert(engine.end(), {0.31f, 0.3f, 0.29f});
        else
            engine.insert(engine.end(), {0.3f, 0.3f, 0.3f});
        mask.push_back(1);
    }
    engine[3 * 7 + 2] = -0.001f;
    reference.insert(reference.end(), {1.0f, 1.0f, 1.0f});
    engine.insert(engine.end(), {-5.0f, 9.0f, 0.0f});
    mask.push_back(0);
    const ImageAccuracy a = measureAccuracy(engine, reference, mask);
    EXPECT_EQ(a.pixels, 100u);
    EXPECT_NEAR(a.negativeFraction, 0.01, 1e-12);
    // (0.31, 0.30) / 0.9 against (1/3, 1/3): |0.3444 - 0.3333| + 0 = 0.0111.
    EXPECT_NEAR(a.chromaticity.p95, 0.01 / 0.9, 1e-5);
    EXPECT_THROW(measureAccuracy(engine, reference, std::vector<std::uint8_t>(3, 1)), Error);
    EXPECT_THROW(measureAccuracy(engine, reference, std::vector<std::uint8_t>(101, 0)), Error);
}

}  // namespace
}  // namespace opal::bench
