// The transfer replayed step by step (bench/transfer_step_gathers.h) on a small bake at the
// shipped defaults: step 1 keeping every Haar coefficient is the lossless sum (the product
// in the Haar domain is the product, E's channels transformed apart); keeping the default
// share leaves an error that shrinks as the share grows; bad input is named.
#include "bench/transfer_step_gathers.h"

#include "bake/bake_pipeline.h"
#include "bench/image_accuracy.h"
#include "schema/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

namespace opal::bench {
namespace {

// The built-in candle at 1,024 samples (4 charts of 16 x 16), the defaults otherwise.
const TranslucentAsset& candle() {
    static const auto asset = [] {
        BakeOptions options;
        options.input = "builtin:candle";
        options.samples = 1024;
        return std::make_shared<const TranslucentAsset>(bakeAsset(options, nullptr, CancelToken{}, nullptr));
    }();
    return *asset;
}

// Light with contrast and colour: dim everywhere, bright and warm on the upward faces.
std::vector<float> contrastyIrradiance(const TranslucentAsset& asset) {
    std::vector<float> e;
    for (const SurfaceSample& s : asset.samples) {
        const float up = std::pow(std::max(0.0f, s.normal.normalized().y), 4.0f);
        e.insert(e.end(), {0.05f + 20.0f * up, 0.05f + 12.0f * up, 0.05f + 6.0f * up});
    }
    return e;
}

TransferSettings keeping(std::uint32_t perRow) {
    TransferSettings s;
    s.minPerRow = perRow;
    return s;
}

TEST(TransferStepGathers, KeepingEveryCoefficientIsTheLosslessSum) {
    const TranslucentAsset& asset = candle();
    const std::vector<float> e = contrastyIrradiance(asset);
    const Material& m = asset.defaultMaterial;
    const std::vector<float> lossless = losslessGather(asset, m, e);
    const std::vector<float> all = step1Gather(asset, m, e, keeping(std::uint32_t(asset.samples.size())));
    EXPECT_LE(measureAccuracy(all, lossless).relativeRmse, 1e-5);
}

TEST(TransferStepGathers, TheDefaultShareLeavesAnErrorThatMoreCoefficientsShrink) {
    const TranslucentAsset& asset = candle();
    const std::vector<float> e = contrastyIrradiance(asset);
    const Material& m = asset.defaultMaterial;
    const std::vector<float> lossless = losslessGather(asset, m, e);
    const double atDefaults = measureAccuracy(step1Gather(asset, m, e, TransferSettings{}), lossless).relativeRmse;
    const double twice = measureAccuracy(step1Gather(asset, m, e, keeping(512)), lossless).relativeRmse;
    std::printf("[ step 1 ] 1,024-sample candle, relative RMSE against lossless: 256 per row %.2e, 512 %.2e\n",
                atDefaults, twice);
    EXPECT_GT(atDefaults, 1e-5);  // a truncation, not a copy
    EXPECT_LT(atDefaults, 0.01);
    EXPECT_LT(twice, 0.5 * atDefaults);
}

TEST(TransferStepGathers, MismatchedIrradianceIsNamed) {
    const TranslucentAsset& asset = candle();
    const std::vector<float> e(3 * asset.samples.size() - 3, 1.0f);
    try {
        losslessGather(asset, asset.defaultMaterial, e);
        FAIL() << "no error";
    } catch (const Error& error) {
        EXPECT_NE(std::string(error.what()).find("3069 irradiance values for 1024 RGB samples"), std::string::npos)
            << error.what();
    }
}

}  // namespace
}  // namespace opal::bench
