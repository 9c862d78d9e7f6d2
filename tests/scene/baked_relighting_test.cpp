// The render delegate issue's accuracy criterion on assets baked here, through the real
// bake: compressed relighting (RelightEngine) against the exact dipole gather
// (referenceGather) under the same lights, relative RMSE over all samples and RGB <= 1%,
// for a point light, a distant light and a dome with a procedural lat-long map, on a small
// baked sphere and torus.
//
// Both sides get the same irradiance: E(x_i; eta) = sum_m c_m(eta) E_m(x_i), the one the
// engine formed from MeshIrradiance's moments (RelightEngine::sampleIrradiance). What is
// left is the engine's own approximation: the K = 12 PCA profile basis (docs/ARCHITECTURE.md#pca)
// and the two-step wavelet compression of the transfer (#compression). The lossless transfer
// (keep 1, energy 1), summed directly here, separates the two: lossless vs reference is
// the basis alone, compressed vs lossless the compression alone. That the engine on a
// lossless bake gives exactly that sum is checked on smaller bakes (a lossless bake of
// 2,048 samples costs ~8 s; the sum well under one).
#include "bake/bake_pipeline.h"
#include "delegate/relight/mesh_irradiance.h"
#include "raytrace/ray_scene.h"
#include "delegate/relight/reference_gather.h"
#include "delegate/relight/relight_engine.h"
#include "tests/bake/bake_test_support.h"
#include "tests/bake/test_meshes.h"

#include <gtest/gtest.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace opal {
namespace {

// 2,048 samples = 2 charts of 32 x 32.
constexpr std::uint64_t kSamples = 2048;

// The compression the test holds to 1%. Measured at 2,048 samples (compressed vs
// reference, per light point / distant / dome; the basis alone is 0.05-0.06% throughout;
// DISABLED_CompressionSweep re-measures):
//   keep 0.01, energy 0.99995 (the defaults)  sphere 6.2 / 6.2 / 5.0%   torus 12.5 / 12.4 / 9.2%
//   keep 0.03, energy 0.99995                 sphere 1.3 / 1.2 / 1.1%   torus 2.1 / 2.5 / 1.7%
//   keep 0.1,  energy 0.9999                  sphere 0.48 / 0.43 / 0.43%  torus 0.80 / 0.80 / 0.67%
//   keep 0.1,  energy 0.99995 (this test)     sphere 0.35 / 0.34 / 0.32%  torus 0.59 / 0.60 / 0.50%
// Step 1's error falls as a row keeps more coefficients across the profile's footprint:
// 1% of 2,048 samples is 21 per row, too few for these small bakes, while the same 1% of
// 65,536 samples (655 per row) leaves the bunny at 0.67% (opal-bench bake).
TransferSettings testedSettings() { return TransferSettings{0.1, TransferSettings{}.energyFraction}; }

// ---- baking -------------------------------------------------------------------------

// The control mesh is in mm (scene units = mm); the default material is marble, whose
// diffusion length (1 / sigma_tr, 8.5 mm in red) is comparable to the objects' size.
std::shared_ptr<const TranslucentAsset> bake(const ControlMesh& control, const std::string& name,
                                             const TransferSettings& transfer, std::uint64_t samples) {
    const test::ScratchDir dir;
    test::writeText(dir / (name + ".obj"), test::objText(control));
    BakeOptions options;
    options.input = (dir / (name + ".obj")).string();
    options.level = 1;
    options.samples = samples;
    options.unitsPerMm = 1.0;
    options.material = "marble";
    options.basisCount = 12;
    options.transfer = transfer;
    options.visibility.cubeFaceSize = 16;
    options.visibility.terms = 64;
    return std::make_shared<const TranslucentAsset>(bakeAsset(options, nullptr, CancelToken{}, nullptr));
}

struct Shape {
    const char* name;
    ControlMesh control;
};

Shape sphere() { return {"sphere", test::icosphere(2, 10.0f)}; }          // radius 10 mm
Shape torus() { return {"torus", test::torus(12.0f, 5.0f, 16, 8)}; }      // 34 mm across, 10 mm thick

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

// The lossless transfer's radiance summed directly, L(x_o) = (1/pi) sum_k s_k (T_k E)(x_o)
// (docs/ARCHITECTURE.md#transfer), with T_k[o][i] = b_k(|x_o - x_i|) A_i off the diagonal
// (BasisLookup, the table the bake evaluates) and T_k[o][o] = the integral of b_k over the sample's
// own disk (transferSelfTerms). A bake with keep = energy = 1 stores exactly this matrix.
std::vector<float> basisGather(const TranslucentAsset& asset, const Material& material, std::span<const float> e) {
    const std::size_t n = asset.samples.size(), K = std::size_t(asset.basis.K());
    const std::array<std::vector<double>, 3> s = asset.basis.project(material);
    const BasisLookup lookup(asset.basis);
    const double toMm = 1.0 / asset.unitsPerMm;
    std::vector<float> radiance(3 * n);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 16), [&](const tbb::blocked_range<std::size_t>& range) {
        std::vector<float> b(K);
        std::vector<double> self(K);
        for (std::size_t o = range.begin(); o != range.end(); ++o) {
            const Imath::V3f xo = asset.samples[o].position;
            double sum[3] = {0.0, 0.0, 0.0};
            for (std::size_t i = 0; i < n; ++i) {
                if (i == o) continue;
                lookup.evaluate(float((asset.samples[i].position - xo).length() * toMm), b.data());
                const double area = asset.samples[i].area * toMm * toMm;
                for (int c = 0; c < 3; ++c) {
                    double profile = 0.0;
                    for (std::size_t k = 0; k < K; ++k) profile += s[c][k] * b[k];
                    sum[c] += profile * area * e[3 * i + c];
                }
            }
            asset.basis.diskIntegrals(std::sqrt(asset.samples[o].area / std::numbers::pi) * toMm, self);
            for (int c = 0; c < 3; ++c) {
                double disk = 0.0;
                for (std::size_t k = 0; k < K; ++k) disk += s[c][k] * self[k];
                radiance[3 * o + c] = float((sum[c] + disk * e[3 * o + c]) / std::numbers::pi);
            }
        }
    });
    return radiance;
}

// sqrt(sum (a - b)^2 / sum b^2) over every sample and channel.
double relativeRmse(std::span<const float> a, std::span<const float> b) {
    double error = 0.0, norm = 0.0;
    for (std::size_t j = 0; j < b.size(); ++j) {
        const double d = double(a[j]) - double(b[j]);
        error += d * d;
        norm += double(b[j]) * double(b[j]);
    }
    return std::sqrt(error / norm);
}

// ---- the measurement ----------------------------------------------------------------

struct Errors {
    double compressed = 0.0;   // the engine vs the reference: the criterion
    double basis = 0.0;        // the lossless transfer vs the reference: the PCA basis alone
    double compression = 0.0;  // the engine vs the lossless transfer: the compression alone
    double exactFresnel = 0.0; // the engine vs a reference fed the exact F_t irradiance
};

Errors measure(const std::shared_ptr<const TranslucentAsset>& asset, LightCase light) {
    const MeshIrradiance irradiance = irradianceOf(asset, light);
    RelightEngine engine(asset);
    engine.setIrradiance(irradiance.moments());
    const Material& m = engine.material();
    const std::span<const float> e = engine.sampleIrradiance();
    const std::vector<float> reference = referenceGather(*asset, m, e);
    const std::vector<float> lossless = basisGather(*asset, m, e);
    const std::vector<float> exactFresnel = referenceGather(*asset, m, irradiance.exactIrradiance(m.eta));
    return {relativeRmse(engine.sampleRadiance(), reference), relativeRmse(lossless, reference),
            relativeRmse(engine.sampleRadiance(), lossless), relativeRmse(engine.sampleRadiance(), exactFresnel)};
}

void expectWithinOnePercent(const Shape& shape) {
    const auto asset = bake(shape.control, shape.name, testedSettings(), kSamples);
    for (LightCase light : kLights) {
        const Errors e = measure(asset, light);
        std::printf("[ accuracy ] %s %s %.2f%% (basis alone %.3f%%, compression alone %.2f%%; "
                    "vs a reference with exact F_t irradiance %.2f%%)\n",
                    shape.name, name(light), 100.0 * e.compressed, 100.0 * e.basis, 100.0 * e.compression,
                    100.0 * e.exactFresnel);
        EXPECT_LE(e.compressed, 0.01) << shape.name << ' ' << name(light);
        // The basis must leave most of the budget to the compression.
        EXPECT_LE(e.basis, 0.005) << shape.name << ' ' << name(light);
    }
}

// ---- the tests ----------------------------------------------------------------------

TEST(BakedRelighting, SphereMatchesTheExactGatherWithinOnePercent) { expectWithinOnePercent(sphere()); }
TEST(BakedRelighting, TorusMatchesTheExactGatherWithinOnePercent) { expectWithinOnePercent(torus()); }

// The engine on a lossless bake (keep 1, energy 1) is the direct sum above up to the
// binary16 rounding of its working transfer (delegate/relight/transfer_product.h: 2^-11 per entry,
// measured 5e-4 to 8e-4 relative RMSE after the Haar domain's cancellations), so the
// "basis alone" numbers are the lossless bake's. 512 samples (2 charts
// of 16 x 16) keep the dense bake cheap.
TEST(BakedRelighting, LosslessBakeLeavesOnlyTheBasisError) {
    for (const Shape& shape : {sphere(), torus()}) {
        const auto asset = bake(shape.control, shape.name, TransferSettings{1.0, 1.0}, 512);
        for (LightCase light : kLights) {
            RelightEngine engine(asset);
            engine.setIrradiance(irradianceOf(asset, light).moments());
            const std::span<const float> e = engine.sampleIrradiance();
            const double vsSum = relativeRmse(engine.sampleRadiance(), basisGather(*asset, engine.material(), e));
            const double vsReference =
                relativeRmse(engine.sampleRadiance(), referenceGather(*asset, engine.material(), e));
            std::printf("[ lossless ] %s %s (512 samples): vs the direct sum %.1e, vs the reference %.3f%%\n",
                        shape.name, name(light), vsSum, 100.0 * vsReference);
            EXPECT_LE(vsSum, 2e-3) << shape.name << ' ' << name(light);
            EXPECT_LE(vsReference, 0.005) << shape.name << ' ' << name(light);
        }
    }
}

// The table in the comment on testedSettings(), re-measured (run on demand with
// --gtest_also_run_disabled_tests; 2.5 minutes on this machine).
TEST(BakedRelighting, DISABLED_CompressionSweep) {
    for (const Shape& shape : {sphere(), torus()})
        for (double keep : {0.01, 0.03, 0.1})
            for (double energy : {0.9999, TransferSettings{}.energyFraction, 1.0}) {
                const auto asset = bake(shape.control, shape.name, TransferSettings{keep, energy}, kSamples);
                for (LightCase light : kLights) {
                    const Errors e = measure(asset, light);
                    std::printf("[ sweep    ] %s keep %.2f energy %.5f %s: %.2f%% (basis alone %.3f%%, "
                                "compression alone %.2f%%)\n",
                                shape.name, keep, energy, name(light), 100.0 * e.compressed, 100.0 * e.basis,
                                100.0 * e.compression);
                }
            }
}

}  // namespace
}  // namespace opal
