#include "delegate/relight/environment_light.h"
#include "delegate/relight/environment_vectors.h"

#include "delegate/relight/mesh_irradiance.h"
#include "schema/error.h"
#include "synthetic_asset.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace opal {
namespace {


void expectDirection(const Imath::V3d& d, const Imath::V3d& expected) {
    EXPECT_NEAR((d - expected).length(), 0.0, 1e-12) << d << " vs " << expected;
}

TEST(LatLongMap, FollowsTheOpenExrAndUsdLuxOrientation) {
    expectDirection(LatLongMap::direction(0.5, 0.5), {0, 0, 1});    // image centre: +Z
    expectDirection(LatLongMap::direction(0.25, 0.5), {1, 0, 0});   // a quarter in: +X
    expectDirection(LatLongMap::direction(0.75, 0.5), {-1, 0, 0});
    expectDirection(LatLongMap::direction(0.0, 0.5), {0, 0, -1});   // edges: -Z
    expectDirection(LatLongMap::direction(0.3, 0.0), {0, 1, 0});    // top row: +Y
    for (double u : {0.1, 0.4, 0.8})
        for (double v : {0.2, 0.5, 0.9}) {
            const Imath::V2d uv = LatLongMap::coordinates(LatLongMap::direction(u, v) * 3.0);
            EXPECT_NEAR(uv.x, u, 1e-12);
            EXPECT_NEAR(uv.y, v, 1e-12);
        }
}

TEST(LatLongMap, RejectsInconsistentPixels) {
    EXPECT_THROW(LatLongMap(4, 2, std::vector<float>(23)), Error);
    std::vector<float> pixels(24, 1.0f);
    pixels[5] = std::numeric_limits<float>::infinity();
    EXPECT_THROW(LatLongMap(4, 2, pixels), Error);
}

// A map of f(direction) sampled at pixel centres.
TEST(EnvironmentLight, CubeTexelsSeeTheMapInTheRightDirection) {
    // Red from +X, green from +Y, blue from +Z, nothing elsewhere.
    const auto map = test::latLongMap(256, 128, [](const Imath::V3d& d) {
        return Imath::V3f(d.x > 0.9 ? 1.0f : 0.0f, d.y > 0.9 ? 1.0f : 0.0f, d.z > 0.9 ? 1.0f : 0.0f);
    });
    const CubeMapLayout cube(8);
    const std::vector<float> radiance = EnvironmentLight(map, Imath::M44d(), Rgb(1.0)).cubeRadiance(cube, Imath::M44d());
    const auto at = [&](const Imath::V3f& d, int c) { return radiance[cube.lookup(d) * 3 + c]; };
    EXPECT_GT(at({1, 0.01f, 0.01f}, 0), 0.9f);
    EXPECT_GT(at({0.01f, 1, 0.01f}, 1), 0.9f);
    EXPECT_GT(at({0.01f, 0.01f, 1}, 2), 0.9f);
    EXPECT_EQ(at({-1, 0.01f, 0.01f}, 0), 0.0f);
    EXPECT_EQ(at({0.01f, 0.01f, -1}, 2), 0.0f);
}

// A slab of samples with normal +Y seeing the whole upper hemisphere: visible transport
// vectors, or occluded residuals, which are then empty.
std::shared_ptr<TranslucentAsset> hemisphereAsset(std::uint32_t faceSize, std::uint32_t terms,
                                                  EnvironmentVectorKind kind = EnvironmentVectorKind::Visible) {
    auto asset = std::make_shared<TranslucentAsset>();
    test::makeSlab(*asset, 1, 1, 1, 1.0f);
    asset->range = EditableRange::coveringPresets();
    asset->environment = test::environmentTransfer(*asset, faceSize, terms, [](std::size_t, const Imath::V3f&) { return true; });
    if (kind == EnvironmentVectorKind::Occluded) {
        EnvironmentTransfer& env = asset->environment;
        env.kind = kind;
        env.offsets.assign(env.offsets.size(), 0);
        env.indices.clear();
        env.values.clear();
    }
    return asset;
}

Imath::M44d rotationY(double degrees) {
    Imath::M44d m;
    m.setAxisAngle(Imath::V3d(0, 1, 0), degrees * std::numbers::pi / 180.0);
    return m;
}

void expectLinearSkyMoments(const std::shared_ptr<TranslucentAsset>& asset, double a, const Imath::V3d& b,
                            const std::shared_ptr<LatLongMap>& map) {
    const char* kindName = asset->environment.kind == EnvironmentVectorKind::Occluded ? " (occluded residuals)" : "";
    hd::LightDesc desc;
    desc.kind = hd::LightKind::Dome;
    desc.intensity = 0.5;
    desc.exposure = 1.0;  // scale 1
    // The mesh as is (normal +Y) and turned by -90 degrees about X (normal along Z).
    Imath::M44d toMinusZ;
    toMinusZ.setAxisAngle(Imath::V3d(1, 0, 0), -std::numbers::pi / 2);
    for (const Imath::M44d& meshTransform : {Imath::M44d(), toMinusZ}) {
        Imath::V3d n;
        meshTransform.multDirMatrix(Imath::V3d(0, 1, 0), n);
        MeshIrradiance irradiance(asset, meshTransform);
        irradiance.setLight("/dome", std::make_shared<EnvironmentLight>(EnvironmentLight::fromDesc(map, desc)));
        const double e0 = std::numbers::pi * a + 2.0 * std::numbers::pi / 3.0 * b.dot(n), e1 = std::numbers::pi / 3.0 * (a + b.dot(n));
        for (std::uint32_t i = 0; i < asset->samples.size(); ++i) {
            EXPECT_NEAR(irradiance.moments().sample(i)[0], e0, 0.005 * e0) << "normal " << n << kindName;
            EXPECT_NEAR(irradiance.moments().sample(i)[3], e1, 0.01 * e1) << "normal " << n << kindName;
        }
    }
}

// On both kinds of vector: the visible transport dotted with the sky, and the dome's
// unoccluded integral (dome_convolution.h) minus nothing.
TEST(EnvironmentLight, LinearSkyGivesClosedFormMoments) {
    // L(w) = a + b.w: E_0 = integral L mu dw = pi a + (2 pi / 3) b.n and
    // E_1 = integral L mu (2 mu - 1) dw = (pi / 3)(a + b.n), for an unoccluded normal n.
    const double a = 2.0;
    const Imath::V3d b(0.5, 0.8, -0.3);
    const auto map = test::latLongMap(512, 256, [&](const Imath::V3d& d) { return Imath::V3f(float(a + b.dot(d))); });
    for (EnvironmentVectorKind kind : {EnvironmentVectorKind::Visible, EnvironmentVectorKind::Occluded})
        expectLinearSkyMoments(hemisphereAsset(32, 2, kind), a, b, map);
}

// Open samples of both kinds: the visible transport, and occluded residuals with nothing
// occluded, where E is the dome's unoccluded integral alone, kept in the dome's frame and
// read at turned normals.
void expectDomeRotationEqualsShiftedMap(EnvironmentVectorKind kind) {
    // Rotating the dome by 90 degrees about +Y brings what the map shows at +Z (u = 1/2) to
    // world +X (u = 1/4): the same as the unrotated map shifted left by a quarter width.
    const int width = 64, height = 32;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> uniform(0.0f, 2.0f);
    std::vector<float> pixels(std::size_t(width) * height * 3);
    for (float& p : pixels) p = uniform(rng);
    std::vector<float> shifted(pixels.size());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c)
                shifted[(std::size_t(y) * width + x) * 3 + c] = pixels[(std::size_t(y) * width + (x + width / 4) % width) * 3 + c];

    Imath::V3d z;
    rotationY(90).multDirMatrix(Imath::V3d(0, 0, 1), z);
    ASSERT_NEAR((z - Imath::V3d(1, 0, 0)).length(), 0.0, 1e-12);  // +Z -> +X

    auto asset = std::make_shared<TranslucentAsset>();
    test::makeCubeSphere(*asset, 2, 1.0f);
    asset->range = EditableRange::coveringPresets();
    asset->environment = test::environmentTransfer(*asset, 8, 2, [](std::size_t, const Imath::V3f&) { return true; });
    if (kind == EnvironmentVectorKind::Occluded) {
        asset->environment.kind = kind;
        asset->environment.offsets.assign(asset->environment.offsets.size(), 0);
        asset->environment.indices.clear();
        asset->environment.values.clear();
    }
    const auto moments = [&](std::vector<float> map, const Imath::M44d& dome) {
        MeshIrradiance irradiance(asset, Imath::M44d());
        irradiance.setLight("/dome", std::make_shared<EnvironmentLight>(
                                         std::make_shared<LatLongMap>(width, height, std::move(map)), dome, Rgb(1.0)));
        return irradiance.moments().values;
    };
    // The integral's 65 x 65 grid is read at the turned normals, between other nodes than the
    // shifted map's: its interpolation (dome_convolution.h: 0.05% median) is the tolerance.
    const double tolerance = kind == EnvironmentVectorKind::Occluded ? 1e-3 : 1e-5;
    const std::vector<float> rotated = moments(pixels, rotationY(90));
    const std::vector<float> shiftedMap = moments(shifted, Imath::M44d());
    EXPECT_LT(test::maxRelative(rotated, shiftedMap), tolerance);
    EXPECT_GT(test::maxRelative(moments(pixels, Imath::M44d()), shiftedMap), 1e-2);  // the rotation matters
    // A uniform scale on the dome changes nothing.
    Imath::M44d scaled;
    scaled.setScale(3.0);
    EXPECT_LT(test::maxRelative(moments(pixels, scaled * rotationY(90)), shiftedMap), tolerance);
}

TEST(EnvironmentLight, DomeRotationEqualsShiftedMap) {
    for (EnvironmentVectorKind kind : {EnvironmentVectorKind::Visible, EnvironmentVectorKind::Occluded}) {
        SCOPED_TRACE(kind == EnvironmentVectorKind::Occluded ? "occluded residuals" : "visible transport");
        expectDomeRotationEqualsShiftedMap(kind);
    }
}

// The unoccluded integral a mesh keeps across a rotation: turning the dome, and then its map
// or colour, gives the bytes a mesh lit by that dome from the start gets.
TEST(EnvironmentLight, AKeptDomeIntegralFollowsEveryChangeButTheTransform) {
    const auto asset = hemisphereAsset(16, 2, EnvironmentVectorKind::Occluded);
    const auto map = test::latLongMap(64, 32, [](const Imath::V3d& d) { return Imath::V3f(float(1.0 + d.x), 1.0f, float(1.5 + d.z)); });
    const auto other = test::latLongMap(64, 32, [](const Imath::V3d& d) { return Imath::V3f(1.0f, float(2.0 - d.y), 1.0f); });
    const auto dome = [](const std::shared_ptr<LatLongMap>& m, double degrees, double scale) {
        return std::make_shared<EnvironmentLight>(m, rotationY(degrees), Rgb(scale));
    };
    const auto fresh = [&](const std::shared_ptr<const EnvironmentLight>& light) {
        MeshIrradiance irradiance(asset, Imath::M44d());
        irradiance.setLight("/dome", light);
        return irradiance.moments().values;
    };
    MeshIrradiance kept(asset, Imath::M44d());
    kept.setLight("/dome", dome(map, 0, 1.0));
    for (const auto& light : {dome(map, 40, 1.0), dome(map, 40, 2.0), dome(other, 40, 2.0), dome(other, 0, 2.0)}) {
        kept.setLight("/dome", light);
        EXPECT_EQ(kept.moments().values, fresh(light));
    }
}

// The per-sample union layout against the plain sum over the sidecar's rows, with rows of
// one sample that keep different positions (which the bake never writes, but a file may).
// Face size 128 has 98,304 texels: 32-bit positions.
void expectSumOverStoredRows(std::uint32_t faceSize, std::uint32_t density, std::uint32_t terms) {
    const std::uint32_t samples = 50, texels = 6 * faceSize * faceSize;
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> value(-1.0f, 1.0f);
    EnvironmentTransfer t;
    t.cubeFaceSize = faceSize;
    t.fresnelTerms = terms;
    t.offsets.push_back(0);
    for (std::uint32_t r = 0; r < samples * terms; ++r) {
        for (std::uint32_t j = 0; j < texels; ++j)
            if (rng() % density == 0) t.indices.push_back(j), t.values.push_back(value(rng));
        t.offsets.push_back(std::uint32_t(t.indices.size()));
    }
    std::vector<float> radiance(texels * 3);
    for (float& l : radiance) l = value(rng);
    for (bool avx2 : {false, true}) {
        IrradianceMoments moments(samples, terms);
        moments.values.assign(moments.values.size(), 0.5f);  // addIrradiance adds
        EnvironmentVectors vectors(t, samples, avx2);
        if (avx2 && !vectors.usesAvx2()) continue;  // this CPU has only the portable loop
        // A call before, with other radiance and weight: the padded radiance the vectors
        // keep between calls must hold this call's.
        IrradianceMoments before(samples, terms);
        vectors.addIrradiance(std::vector<float>(radiance.rbegin(), radiance.rend()), before, -2.0f);
        vectors.addIrradiance(radiance, moments);
        for (std::uint32_t r = 0; r < samples * terms; ++r)
            for (int c = 0; c < 3; ++c) {
                double sum = 0.5, bound = 0.0;  // binary16 values: 2^-11 of each term
                for (std::uint32_t e = t.offsets[r]; e < t.offsets[r + 1]; ++e) {
                    sum += double(t.values[e]) * radiance[t.indices[e] * 3 + c];
                    bound += std::abs(double(t.values[e]) * radiance[t.indices[e] * 3 + c]);
                }
                ASSERT_NEAR(moments.values[r * 3 + c], sum, std::ldexp(bound, -11) + 1e-6)
                    << "row " << r << " channel " << c << (avx2 ? " (avx2)" : "");
            }
    }
}

TEST(EnvironmentVectors, EqualTheSumOverTheStoredRows) {
    for (std::uint32_t terms : {1u, 2u, 3u}) expectSumOverStoredRows(4, 4, terms);
    expectSumOverStoredRows(128, 256, 2);
}

TEST(EnvironmentLight, RejectsMismatchedTransfer) {
    const auto asset = hemisphereAsset(4, 2);
    IrradianceMoments wrongTerms(std::uint32_t(asset->samples.size()), 1);
    const std::vector<float> radiance(6 * 4 * 4 * 3, 1.0f);
    EnvironmentVectors vectors(asset->environment, asset->samples.size());
    EXPECT_THROW(vectors.addIrradiance(radiance, wrongTerms), Error);
    IrradianceMoments moments(std::uint32_t(asset->samples.size()), 2);
    EXPECT_THROW(vectors.addIrradiance(std::span(radiance).first(30), moments), Error);
    EXPECT_THROW(EnvironmentVectors(asset->environment, asset->samples.size() + 1), Error);
    EnvironmentTransfer outside = asset->environment;
    outside.indices[3] = 6 * 4 * 4;
    EXPECT_THROW(EnvironmentVectors(outside, asset->samples.size()), Error);
}

}  // namespace
}  // namespace opal
