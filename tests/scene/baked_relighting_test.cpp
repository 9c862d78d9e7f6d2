// Accuracy at the shipped defaults, on small assets baked here through the real bake (a
// sphere, a torus, the concave built-in candle): the relighting engine (RelightEngine)
// against the exact dipole gather (referenceGather) for a point light, a distant light and
// a dome with a procedural lat-long map, with issue 13's figures per sample
// (bench/image_accuracy.h). Asserted for every light: relative RMSE <= 1%, the 95th
// percentile of the relative luminance error <= 3% and of the chromaticity error <= 0.005,
// no negative radiance. Measured at 2,048 samples with the 36-function harmonic transfer
// (docs/ARCHITECTURE.md#harmonic-transfer) and the profile fit of #pca (2026-11-27): point
// p95 0.4-2.7%, chromaticity 0.0014-0.0043; distant p95 0.5-1.0%, chromaticity
// 0.0010-0.0031; dome p95 0.4-0.5%, chromaticity 0.0004-0.0005. With the nine normal
// harmonics alone the torus's point light missed the chromaticity target (p95 2.6%,
// chromaticity 0.0071): a near light falls off with distance across the object, which the
// normal cannot tell, and what the compressed matrices carry of it leaves an absolute error
// that samples lit only through the profile's far tail show large (#compression, "Small
// objects under a point light").
//
// The lossless transfer (keep 1, energy 1), summed directly here, separates the PCA
// profile basis (docs/ARCHITECTURE.md#pca) from the two-step wavelet compression
// (#compression): lossless vs reference is the basis alone. That the engine on a lossless
// bake gives exactly that sum is checked on smaller bakes.
#include "bake/bake_pipeline.h"
#include "bench/image_accuracy.h"
#include "bench/transfer_step_gathers.h"
#include "delegate/relight/mesh_irradiance.h"
#include "raytrace/ray_scene.h"
#include "delegate/relight/reference_gather.h"
#include "delegate/relight/relight_engine.h"
#include "schema/asset/self_term.h"
#include "schema/scatter/dipole.h"
#include "schema/scatter/profile_projection.h"
#include "tests/bake/bake_test_support.h"
#include "tests/bake/test_meshes.h"

#include <gtest/gtest.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace opal {
namespace {

// 2,048 samples = 2 charts of 32 x 32: small enough for a test, and the shipped defaults
// must hold there too (bake/transfer_builder.h: TransferSettings::minPerRow).
constexpr std::uint64_t kSamples = 2048;

// ---- baking -------------------------------------------------------------------------

// The shipped defaults (BakeOptions{}) but for the sample count. Control meshes are in mm
// (scene units = mm); the default material is marble, whose diffusion length (1 / sigma_tr,
// 8.5 mm in red) is comparable to the objects' size.
std::shared_ptr<const TranslucentAsset> bake(const std::string& input, std::uint64_t samples,
                                             const TransferSettings& transfer = TransferSettings{}) {
    BakeOptions options;
    options.input = input;
    options.samples = samples;
    options.transfer = transfer;
    return std::make_shared<const TranslucentAsset>(bakeAsset(options, nullptr, CancelToken{}, nullptr));
}

struct Shape {
    const char* name;
    std::optional<ControlMesh> control;  // empty: builtin:<name>
};

std::shared_ptr<const TranslucentAsset> bake(const Shape& shape, std::uint64_t samples,
                                             const TransferSettings& transfer = TransferSettings{}) {
    if (!shape.control) return bake(std::string("builtin:") + shape.name, samples, transfer);
    const test::ScratchDir dir;
    test::writeText(dir / (std::string(shape.name) + ".obj"), test::objText(*shape.control));
    return bake((dir / (std::string(shape.name) + ".obj")).string(), samples, transfer);
}

Shape sphere() { return {"sphere", test::icosphere(2, 10.0f)}; }          // radius 10 mm
Shape torus() { return {"torus", test::torus(12.0f, 5.0f, 16, 8)}; }      // 34 mm across, 10 mm thick
// Concave: the built-in candle's melted top is a bowl inside a raised rim (40 mm across).
Shape candle() { return {"candle", std::nullopt}; }

// ---- lights -------------------------------------------------------------------------

hd::LightDesc pointLight() {
    hd::LightDesc d;
    d.kind = hd::LightKind::Sphere;
    d.treatAsPoint = true;
    d.intensity = 2000.0;
    d.transform.setTranslation(Imath::V3d(30, 40, 25));
    return d;
}

hd::LightDesc distantLight() {
    hd::LightDesc d;
    d.kind = hd::LightKind::Distant;
    d.normalize = true;
    d.color = {1.0, 0.8, 0.6};
    d.transform.setAxisAngle(Imath::V3d(1, 0.3, 0).normalized(), 2.2);
    return d;
}

// A sky with directional structure, 64 x 32 pixels: a small bright warm sun, a blue sky
// brighter overhead, a dark ground.
std::shared_ptr<const LatLongMap> skyMap() {
    const int width = 64, height = 32;
    const Imath::V3d sun = Imath::V3d(0.5, 0.7, 0.5).normalized();
    std::vector<float> rgb;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Imath::V3d d = LatLongMap::direction((x + 0.5) / width, (y + 0.5) / height);
            const double glow = 30.0 * std::exp(-(1.0 - d.dot(sun)) / 0.02);
            const Imath::V3d sky =
                d.y > 0 ? Imath::V3d(0.2, 0.3, 0.6) * (0.4 + d.y) : Imath::V3d(0.05, 0.04, 0.03);
            const Imath::V3d v = sky + Imath::V3d(1.0, 0.9, 0.7) * glow;
            rgb.insert(rgb.end(), {float(v.x), float(v.y), float(v.z)});
        }
    return std::make_shared<const LatLongMap>(width, height, std::move(rgb));
}

enum class LightCase { Point, Distant, Dome };
constexpr LightCase kLights[] = {LightCase::Point, LightCase::Distant, LightCase::Dome};

const char* name(LightCase light) {
    return light == LightCase::Point ? "point" : light == LightCase::Distant ? "distant" : "dome";
}

// The light on the asset at the origin, the asset shadowing itself.
MeshIrradiance irradianceOf(const std::shared_ptr<const TranslucentAsset>& asset, LightCase light) {
    RayScene rays;
    rays.addMesh(asset->mesh, Imath::M44d());
    rays.commit();
    MeshIrradiance irradiance(asset, Imath::M44d());
    if (light == LightCase::Point) irradiance.setLight("/light", AnalyticLight::fromDesc(pointLight()), rays);
    if (light == LightCase::Distant) irradiance.setLight("/light", AnalyticLight::fromDesc(distantLight()), rays);
    if (light == LightCase::Dome)
        irradiance.setLight("/light", std::make_shared<const EnvironmentLight>(skyMap(), Imath::M44d(), Rgb(1.0)));
    return irradiance;
}

// ---- truths -------------------------------------------------------------------------

// The lossless transfer's radiance summed directly (bench/transfer_step_gathers.h): every
// pair of samples through the basis table the bake evaluates, s_k fitted beyond the
// sample's own disk, and the self term the engine adds. A bake with keep = energy = 1
// stores exactly this matrix.
using bench::losslessGather;

// sqrt(sum (a - b)^2 / sum b^2) over every sample and channel.
double relativeRmse(std::span<const float> a, std::span<const float> b) {
    return bench::measureAccuracy(a, b).relativeRmse;
}

// ---- the measurement ----------------------------------------------------------------

// The engine against the exact dipole gather over the asset's samples, with the figures of
// `opal-bench accuracy` (bench/image_accuracy.h) taken per sample instead of per pixel.
// Analytic lights: both sides get the engine's E (the moments combined at the material's
// eta), so what is measured is the engine's own approximation. The dome: the reference
// gets the brute-force hemisphere integral of the map (MeshIrradiance::referenceIrradiance:
// Embree visibility, exact F_t), so the baked, truncated visibility vectors and the
// Fresnel-moment fit are measured too.
struct Measured {
    bench::ImageAccuracy figures;
    double basis = 0.0;  // the lossless transfer vs the same reference: the PCA basis alone
    RelightEngine::NegativeNoise noise;  // what the engine set to zero
    double zeroedTruth = 0.0;            // the highest exact L (over the peak) where the engine gave 0
    double zeroedIrradianceTruth = 0.0;  // the same for E (a dome's truncated visibility)
    std::size_t negativeIrradiance = 0;  // values of the engine's E below zero
};

// Over the values the engine gave as 0: the highest exact L there, as a fraction of the
// exact peak. The engine sets to zero only what its compression noise took below zero, so
// this is the noise's size, not the image's.
double highestZeroedTruth(std::span<const float> engine, std::span<const float> reference) {
    float peak = 0.0f, zeroed = 0.0f;
    for (std::size_t j = 0; j < reference.size(); ++j) {
        peak = std::max(peak, reference[j]);
        if (engine[j] == 0.0f) zeroed = std::max(zeroed, reference[j]);
    }
    return peak > 0.0f ? zeroed / peak : 0.0;
}

Measured measure(const std::shared_ptr<const TranslucentAsset>& asset, LightCase light) {
    MeshIrradiance irradiance = irradianceOf(asset, light);
    RelightEngine engine(asset);
    engine.setIrradiance(irradiance.moments());
    const Material& m = engine.material();
    const std::span<const float> engineE = engine.sampleIrradiance();
    const std::vector<float> referenceE = light == LightCase::Dome
                                              ? irradiance.referenceIrradiance(m.eta)
                                              : std::vector<float>(engineE.begin(), engineE.end());
    const std::vector<float> reference = referenceGather(*asset, m, referenceE);
    // The basis alone is measured at the engine's E: for analytic lights that is `reference`.
    const std::vector<float> referenceAtEngineE =
        light == LightCase::Dome ? referenceGather(*asset, m, engineE) : reference;
    return {bench::measureAccuracy(engine.sampleRadiance(), reference),
            relativeRmse(losslessGather(*asset, m, engineE), referenceAtEngineE), engine.radianceNoise(),
            highestZeroedTruth(engine.sampleRadiance(), reference), highestZeroedTruth(engineE, referenceE),
            std::size_t(std::count_if(engineE.begin(), engineE.end(), [](float e) { return e < 0.0f; }))};
}

// The compressed transfer's error near zero, as a fraction of the peak L: at the defaults
// it stays below 1e-3 on these assets (measured: see the printed figures).
constexpr double kNoiseFloor = 2e-3;
// A dome's E carries its residual vectors' truncation error (docs/ARCHITECTURE.md#dome-light):
// where the engine zeroes E, the exact E must be within this fraction of the peak.
constexpr double kDomeNoiseFloor = 1e-2;

void expectAccuracyAtTheDefaults(const Shape& shape) {
    const auto asset = bake(shape, kSamples);
    for (LightCase light : kLights) {
        const Measured r = measure(asset, light);
        const bench::ImageAccuracy& a = r.figures;
        std::printf("[ accuracy ] %-6s %-7s rel. RMSE %.2f%%, luminance median %.2f%% p95 %.2f%%, darker half p95 "
                    "%.2f%%, chromaticity p95 %.4f, negative %.4f (basis alone %.3f%%); set to zero %llu "
                    "values, deepest %.1e, exact L there <= %.1e; E: exact E where zeroed <= %.1e\n",
                    shape.name, name(light), 100.0 * a.relativeRmse, 100.0 * a.luminance.median,
                    100.0 * a.luminance.p95, 100.0 * a.darkerHalf.p95, a.chromaticity.p95, a.negativeFraction,
                    100.0 * r.basis, static_cast<unsigned long long>(r.noise.values), r.noise.deepest, r.zeroedTruth,
                    r.zeroedIrradianceTruth);
        EXPECT_LE(a.relativeRmse, 0.01) << shape.name << ' ' << name(light);
        EXPECT_LE(a.luminance.p95, 0.03) << shape.name << ' ' << name(light);
        EXPECT_LE(a.chromaticity.p95, 0.005) << shape.name << ' ' << name(light);
        // The basis must leave most of the budget to the compression.
        EXPECT_LE(r.basis, 0.005) << shape.name << ' ' << name(light);
        // No negative radiance, and the zeroing stays within the noise: it happens only where
        // the exact L is below the transfer's error, and never hides a real dip.
        EXPECT_EQ(a.negativeFraction, 0.0) << shape.name << ' ' << name(light);
        EXPECT_LE(r.zeroedTruth, kNoiseFloor) << shape.name << ' ' << name(light);
        EXPECT_GE(r.noise.deepest, -kNoiseFloor) << shape.name << ' ' << name(light);
        EXPECT_EQ(r.negativeIrradiance, 0u) << shape.name << ' ' << name(light);
        EXPECT_LE(r.zeroedIrradianceTruth, kDomeNoiseFloor) << shape.name << ' ' << name(light);
    }
}

// ---- the tests ----------------------------------------------------------------------

TEST(BakedRelighting, SphereAtTheDefaults) { expectAccuracyAtTheDefaults(sphere()); }
TEST(BakedRelighting, TorusAtTheDefaults) { expectAccuracyAtTheDefaults(torus()); }
TEST(BakedRelighting, ConcaveCandleAtTheDefaults) { expectAccuracyAtTheDefaults(candle()); }

// Light that is a combination of the normal harmonics goes entirely through their exact
// transfer (docs/ARCHITECTURE.md#harmonic-transfer): at the shipped compression the engine
// then gives the lossless sum up to float rounding, where the matrices alone (the same
// asset without its harmonic transfer) miss it by the compression's error.
TEST(BakedRelighting, SmoothLightIsRelitExactlyAtTheDefaults) {
    const auto asset = bake(torus(), kSamples);
    ASSERT_FALSE(asset->transfer.harmonics.empty());
    IrradianceMoments smooth(std::uint32_t(asset->samples.size()), 2);
    for (std::size_t i = 0; i < asset->samples.size(); ++i) {
        const Imath::V3f n = asset->samples[i].normal;
        const float e[3] = {1.0f + 0.5f * n.x, 0.8f + 0.3f * n.z * n.z, 0.6f - 0.2f * n.y * n.z};
        for (int c = 0; c < 3; ++c) {
            smooth.sample(i)[c] = e[c];
            smooth.sample(i)[3 + c] = 0.25f * e[c] * (1.0f + n.x * n.y);  // the second moment: smooth too
        }
    }
    auto matricesOnly = std::make_shared<TranslucentAsset>(*asset);
    matricesOnly->transfer.harmonics.clear();
    double errors[2];
    int i = 0;
    for (const auto& a : {asset, std::shared_ptr<const TranslucentAsset>(matricesOnly)}) {
        RelightEngine engine(a);
        engine.setIrradiance(smooth);
        errors[i++] = relativeRmse(engine.sampleRadiance(),
                                   losslessGather(*a, engine.material(), engine.sampleIrradiance()));
    }
    std::printf("[ smooth   ] torus: engine vs the lossless sum %.1e with the harmonic transfer, %.1e without\n",
                errors[0], errors[1]);
    EXPECT_LE(errors[0], 1e-4);
    EXPECT_GE(errors[1], 10.0 * errors[0]);
}

// The engine on a lossless bake (keep 1, energy 1) is the direct sum above up to the
// binary16 rounding of its working transfer (delegate/relight/transfer_product.h: 2^-11 per
// entry; measured 3.0e-4 to 4.4e-4 relative RMSE with the nine normal harmonics, 4e-6 to
// 8e-6 with the 36 functions, which leave the matrices less of the light), so the
// "basis alone" numbers are the lossless bake's. 512 samples (2 charts
// of 16 x 16) keep the dense bake cheap.
TEST(BakedRelighting, LosslessBakeLeavesOnlyTheBasisError) {
    for (const Shape& shape : {sphere(), torus()}) {
        const auto asset = bake(shape, 512, TransferSettings{1.0, 1.0});
        for (LightCase light : kLights) {
            RelightEngine engine(asset);
            engine.setIrradiance(irradianceOf(asset, light).moments());
            const std::span<const float> e = engine.sampleIrradiance();
            const double vsSum = relativeRmse(engine.sampleRadiance(), losslessGather(*asset, engine.material(), e));
            const double vsReference =
                relativeRmse(engine.sampleRadiance(), referenceGather(*asset, engine.material(), e));
            std::printf("[ lossless ] %s %s (512 samples): vs the direct sum %.1e, vs the reference %.3f%%\n",
                        shape.name, name(light), vsSum, 100.0 * vsReference);
            EXPECT_LE(vsSum, 2e-3) << shape.name << ' ' << name(light);
            EXPECT_LE(vsReference, 0.005) << shape.name << ' ' << name(light);
        }
    }
}

}  // namespace
}  // namespace opal
