#include "delegate/relight/reference_gather.h"

#include "delegate/relight/mesh_irradiance.h"
#include "raytrace/ray_scene.h"
#include "delegate/relight/relight_engine.h"
#include "schema/error.h"
#include "schema/scatter/dipole.h"
#include "synthetic_asset.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace opal {
namespace {


TEST(ReferenceGather, SumsTheDipoleOverSamplesInMillimetres) {
    TranslucentAsset asset;
    asset.unitsPerMm = 0.5;  // 2 mm per scene unit
    asset.layout = ChartLayout{2, 0};
    asset.samples = {{{0, 0, 0}, {0, 1, 0}, 0.3f}, {{1.5f, 0, 0}, {0, 1, 0}, 0.2f}};  // 3 mm apart
    const Material m{{1.0, 2.0, 0.5}, {0.1, 0.01, 0.3}, 1.4};
    const std::vector<float> e = {1.0f, 2.0f, 3.0f, 0.5f, 0.25f, 4.0f};
    const std::vector<float> l = referenceGather(asset, m, e);
    for (int c = 0; c < 3; ++c) {
        const double a0 = 0.3 * 4.0, a1 = 0.2 * 4.0;  // mm^2
        // Each sample's own light is gathered over its own disk (radius sqrt(A / pi)).
        const double self0 = dipoleDiskReflectance(std::sqrt(a0 / std::numbers::pi), m.channel(c));
        const double self1 = dipoleDiskReflectance(std::sqrt(a1 / std::numbers::pi), m.channel(c));
        const double expected0 = (self0 * e[c] + dipoleProfile(3.0, m.channel(c)) * a1 * e[3 + c]) / std::numbers::pi;
        const double expected1 = (dipoleProfile(3.0, m.channel(c)) * a0 * e[c] + self1 * e[3 + c]) / std::numbers::pi;
        EXPECT_NEAR(l[c], expected0, 1e-6 * expected0);
        EXPECT_NEAR(l[3 + c], expected1, 1e-6 * expected1);
    }
    const std::uint32_t second[] = {1};
    const std::vector<float> only = referenceGather(asset, m, e, second);
    ASSERT_EQ(only.size(), 3u);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(only[c], l[3 + c]);
    const std::uint32_t outOfRange[] = {2};
    EXPECT_THROW(referenceGather(asset, m, e, outOfRange), Error);
    EXPECT_THROW(referenceGather(asset, m, std::span(e).first(5)), Error);
}

TEST(ReferenceGather, RefusesEtaOutsideTheDipolesRange) {
    TranslucentAsset asset;
    asset.layout = ChartLayout{2, 0};
    asset.samples = {{{0, 0, 0}, {0, 1, 0}, 0.3f}, {{1.5f, 0, 0}, {0, 1, 0}, 0.2f}};
    const std::vector<float> e(6, 1.0f);
    for (double eta : {3.9, 10.0, std::nan(""), 0.5}) {
        const Material m{{1.0, 2.0, 0.5}, {0.1, 0.01, 0.3}, eta};
        try {
            referenceGather(asset, m, e);
            ADD_FAILURE() << "no error for eta " << eta;
        } catch (const Error& error) {
            EXPECT_NE(std::string(error.what()).find("[1, 3]"), std::string::npos) << error.what();
        }
    }
    const Material atTheBound{{1.0, 2.0, 0.5}, {0.1, 0.01, 0.3}, kDipoleEtaMax};
    for (float value : referenceGather(asset, atTheBound, e)) EXPECT_TRUE(std::isfinite(value) && value > 0.0f);
}

// 2 pi integral_0^1 F_t(eta, mu) mu dmu: the irradiance of a uniform unit sky (midpoint rule).
double skyIrradiance(double eta) {
    double sum = 0.0;
    for (int q = 0; q < 20000; ++q) {
        const double mu = (q + 0.5) / 20000.0;
        sum += fresnelTransmittance(eta, mu) * mu / 20000.0;
    }
    return 2.0 * std::numbers::pi * sum;
}

// A slab under a uniform unit dome that each sample sees over its whole upper hemisphere.
std::shared_ptr<TranslucentAsset> furnaceSlab(std::uint32_t chartsPerSide, std::uint32_t log2Size, float spacing,
                                              const Material& material) {
    auto asset = std::make_shared<TranslucentAsset>();
    test::makeSlab(*asset, chartsPerSide, chartsPerSide, log2Size, spacing);
    asset->defaultMaterial = material;
    asset->range = test::rangeAround(material, 2.0, 1.2, 1.6);
    // A uniform sky only meets the face averages: the 64 largest terms carry all of them.
    asset->environment =
        test::environmentTransfer(*asset, 16, 2, [](std::size_t, const Imath::V3f&) { return true; }, 64);
    return asset;
}

MeshIrradiance underUniformSky(const std::shared_ptr<TranslucentAsset>& asset) {
    MeshIrradiance irradiance(asset, Imath::M44d());
    const auto white = std::make_shared<LatLongMap>(8, 4, std::vector<float>(8 * 4 * 3, 1.0f));
    irradiance.setLight("/sky", std::make_shared<EnvironmentLight>(white, Imath::M44d(), Rgb(1.0)));
    return irradiance;
}

// The samples nearest the slab's centre (4 of them).
std::vector<std::uint32_t> centreSamples(const TranslucentAsset& asset) {
    Imath::V3f centre(0.0f);
    for (const SurfaceSample& s : asset.samples) centre += s.position / float(asset.samples.size());
    std::vector<std::uint32_t> out;
    for (std::uint32_t i = 0; i < asset.samples.size(); ++i)
        if ((asset.samples[i].position - centre).length() < 0.75f * std::sqrt(asset.samples[i].area)) out.push_back(i);
    return out;
}

TEST(ReferenceGather, WhiteFurnaceMatchesTotalDiffuseReflectance) {
    const Material m{{1.0, 1.2, 1.5}, {0.3, 0.4, 0.5}, 1.3};
    // 64 x 64 samples 1/8 mm apart: 8 x 8 mm, several diffusion lengths from the centre.
    const auto slab = furnaceSlab(1, 6, 0.125f, m);
    const MeshIrradiance irradiance = underUniformSky(slab);
    const std::vector<float> e = irradiance.exactIrradiance(m.eta);
    const double sky = skyIrradiance(m.eta);
    for (float value : e) EXPECT_NEAR(value, sky, 0.005 * sky);

    const std::vector<std::uint32_t> centre = centreSamples(*slab);
    ASSERT_EQ(centre.size(), 4u);
    const std::vector<float> l = referenceGather(*slab, m, e, centre);
    for (int c = 0; c < 3; ++c) {
        const double alphaPrime = m.sigmaSPrime[c] / (m.sigmaSPrime[c] + m.sigmaA[c]);
        const double expected = dipoleTotalReflectance(alphaPrime, m.eta) * sky / std::numbers::pi;  // (1/pi) R_d,total E
        for (std::size_t j = 0; j < centre.size(); ++j) {
            EXPECT_NEAR(l[3 * j + c], expected, 0.02 * expected) << "channel " << c;
            if (j == 0)
                std::printf("[ furnace  ] reference channel %d: L %.5f, (1/pi) R_total E %.5f (%+.2f%%)\n", c,
                            l[3 * j + c], expected, 100.0 * (l[3 * j + c] / expected - 1.0));
        }
    }
}

TEST(ReferenceGather, WhiteFurnaceThroughThePcaEngine) {
    const Material m{{1.0, 1.2, 1.5}, {0.3, 0.4, 0.5}, 1.3};
    // 2 x 2 charts of 16 x 16 samples 1/4 mm apart: 8 x 8 mm again, coarser.
    auto slab = furnaceSlab(2, 4, 0.25f, m);
    slab->basis = test::fitBasis(slab->range, 8, 12.0);
    test::buildTransfer(*slab, 1.0, 1.0);
    const MeshIrradiance irradiance = underUniformSky(slab);
    RelightEngine engine(slab);
    engine.setIrradiance(irradiance.moments());
    const std::vector<std::uint32_t> centre = centreSamples(*slab);
    ASSERT_EQ(centre.size(), 4u);
    const std::vector<float> reference = referenceGather(*slab, m, irradiance.exactIrradiance(m.eta), centre);
    const double sky = skyIrradiance(m.eta);
    for (int c = 0; c < 3; ++c) {
        const double alphaPrime = m.sigmaSPrime[c] / (m.sigmaSPrime[c] + m.sigmaA[c]);
        const double expected = dipoleTotalReflectance(alphaPrime, m.eta) * sky / std::numbers::pi;
        for (std::size_t j = 0; j < centre.size(); ++j) {
            const float pca = engine.sampleRadiance()[3 * centre[j] + c];
            EXPECT_NEAR(pca, reference[3 * j + c], 0.01 * reference[3 * j + c]) << "channel " << c;
            EXPECT_NEAR(pca, expected, 0.03 * expected) << "channel " << c;
            if (j == 0)
                std::printf("[ furnace  ] PCA engine channel %d: L %.5f, reference %.5f, (1/pi) R_total E %.5f (%+.2f%%)\n",
                            c, pca, reference[3 * j + c], expected, 100.0 * (pca / expected - 1.0));
        }
    }
}

TEST(ReferenceGather, CompressedRelightingOfASphereStaysNearTheReference) {
    auto sphere = std::make_shared<TranslucentAsset>();
    test::makeCubeSphere(*sphere, 3, 5.0f);  // 6 x 8 x 8 samples, radius 5 mm
    sphere->defaultMaterial = Material{{1.2, 0.9, 0.7}, {0.05, 0.1, 0.2}, 1.4};
    sphere->range = test::rangeAround(sphere->defaultMaterial, 2.0, 1.2, 1.6);
    sphere->basis = test::fitBasis(sphere->range, 8, 12.0);
    auto lossless = std::make_shared<TranslucentAsset>(*sphere);
    test::buildTransfer(*sphere, 0.2, 0.999);
    test::buildTransfer(*lossless, 1.0, 1.0);
    RayScene rays;
    rays.addMesh(sphere->mesh, Imath::M44d());
    rays.commit();

    MeshIrradiance irradiance(sphere, Imath::M44d());
    hd::LightDesc point;
    point.kind = hd::LightKind::Sphere;
    point.treatAsPoint = true;
    point.intensity = 40.0;
    point.transform.setTranslation(Imath::V3d(9, 6, 3));
    irradiance.setLight("/point", AnalyticLight::fromDesc(point), rays);
    hd::LightDesc sun;
    sun.kind = hd::LightKind::Distant;
    sun.normalize = true;
    sun.color = {0.3, 0.5, 1.0};
    sun.transform.setAxisAngle(Imath::V3d(1, 0, 0), 2.0);
    irradiance.setLight("/sun", AnalyticLight::fromDesc(sun), rays);

    RelightEngine compressed(sphere), exact(lossless);
    compressed.setIrradiance(irradiance.moments());
    exact.setIrradiance(irradiance.moments());
    for (const Material& m : {sphere->defaultMaterial, Material{{0.8, 1.3, 1.0}, {0.08, 0.06, 0.3}, 1.55}}) {
        compressed.setMaterial(m);
        exact.setMaterial(m);
        const std::vector<float> reference = referenceGather(*sphere, m, irradiance.exactIrradiance(m.eta));
        const double pcaError = test::relativeRmse(exact.sampleRadiance(), reference);
        const double error = test::relativeRmse(compressed.sampleRadiance(), reference);
        std::printf("[ sphere   ] eta %.2f vs reference gather: lossless transfer (K = 8 PCA, Fresnel moments) "
                    "relative RMSE %.4f; compressed (20%% Haar, 99.9%% energy) %.4f\n", m.eta, pcaError, error);
        EXPECT_LT(pcaError, 0.002);
        EXPECT_LT(error, 0.025);
    }
}

}  // namespace
}  // namespace opal
