// Evaluating a shadow field (schema/asset/shadow_field_lookup.h) on fields made in code,
// whose values follow known functions: an inverse-square falloff across shells, a smooth
// function of direction across the sample grid and its face edges, the far-field point
// light and the inner-shell fallback.
#include "schema/asset/cube_map.h"
#include "schema/asset/shadow_field_lookup.h"
#include "schema/error.h"
#include "synthetic_shadow_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace opal {
namespace {

Imath::V3d direction(double theta, double phi) {
    return {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
}

// Every texel of a uniform map holds the same value; the map's red channel.
double uniformValue(const std::vector<Imath::V3f>& map) {
    for (const Imath::V3f& t : map) EXPECT_NEAR(t.x, map.front().x, 1e-5 * std::abs(map.front().x) + 1e-12);
    return map.front().x;
}

TEST(ShadowFieldLookup, InverseSquareFalloffIsInterpolatedExactly) {
    ShadowField f;
    f = test::uniformShadowField([&](std::uint32_t shell, std::uint64_t) {
        const double r = 2.5 * std::pow(2.0, double(shell));
        return 100.0 / (r * r);
    });
    const ShadowFieldLookup lookup(f);
    for (double r = f.radii.front(); r <= f.radii.back(); r *= 1.07) {
        const Imath::V3d p = f.centre + direction(0.7, 2.0) * r;
        EXPECT_NEAR(uniformValue(lookup.incidentRadiance(p)), 100.0 / (r * r), 1e-5 * 100.0 / (r * r)) << r;
    }
}

// A smooth function of the sample direction, g(w) = 1 + 0.5 w.x + 0.3 w.y - 0.2 w.z:
// bilinear interpolation on the grid, continued across face edges, follows it closely
// everywhere, edges and corners included (clamping at edges would be off by up to half a
// grid step's change, about 0.1 here).
TEST(ShadowFieldLookup, DirectionInterpolationFollowsASmoothFunctionAcrossFaceEdges) {
    const std::uint32_t grid = 8;
    const CubeMapLayout samples(grid);
    const auto g = [](const Imath::V3d& w) { return 1.0 + 0.5 * w.x + 0.3 * w.y - 0.2 * w.z; };
    const ShadowField f = test::uniformShadowField(
        [&](std::uint32_t, std::uint64_t m) { return g(Imath::V3d(samples.direction(std::uint32_t(m % samples.texels())))); },
        2, grid, 4);
    const ShadowFieldLookup lookup(f);
    double worst = 0.0;
    for (int i = 0; i <= 60; ++i)
        for (int k = 0; k < 120; ++k) {
            const Imath::V3d w = direction(std::numbers::pi * i / 60, 2 * std::numbers::pi * k / 120);
            const double value = uniformValue(lookup.incidentRadiance(f.centre + w * f.radii.front()));
            worst = std::max(worst, std::abs(value - g(w)));
        }
    EXPECT_LT(worst, 0.02);
}

TEST(ShadowFieldLookup, StencilWeightsSumToOne) {
    const ShadowField f = test::uniformShadowField([](std::uint32_t, std::uint64_t) { return 1.0; });
    const ShadowFieldLookup lookup(f);
    for (double r : {0.0, 1.0, 2.5, 3.0, 7.0, 20.0, 25.0}) {
        const FieldStencil s = lookup.stencil(f.centre + direction(1.1, 0.3) * r);
        double sum = 0.0;
        for (std::uint32_t i = 0; i < s.count; ++i) sum += s.maps[i].weight;
        EXPECT_NEAR(sum, 1.0, 1e-12) << r;
        EXPECT_EQ(s.region, r < 2.5 ? FieldRegion::Inside : r > 20.0 ? FieldRegion::Beyond : FieldRegion::Field) << r;
    }
}

// Uniform radiance L from every direction: E = pi L on any surface.
TEST(ShadowFieldLookup, IrradianceOfUniformRadianceIsPiL) {
    const ShadowField f = test::uniformShadowField([](std::uint32_t, std::uint64_t) { return 2.0; });
    const ShadowFieldLookup lookup(f);
    for (const Imath::V3d& n : {Imath::V3d(0, 1, 0), direction(0.4, 1.0), direction(2.0, -0.5)}) {
        const Imath::V3d e = lookup.irradiance(f.centre + Imath::V3d(6.0, 0.0, 0.0), n);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(e[c], std::numbers::pi * 2.0 * (c + 1), 1e-5 * e[c]);
    }
}

// Beyond the outer shell: a point light of intensity I = r_last^2 * 4 pi L (the outer
// maps are uniform L), so E = I cos / d^2 toward the centre, and nothing facing away.
TEST(ShadowFieldLookup, BeyondTheOuterShellIsAPointLight) {
    const ShadowField f = test::uniformShadowField([](std::uint32_t, std::uint64_t) { return 0.5; });
    const ShadowFieldLookup lookup(f);
    const double R = f.radii.back(), intensity = R * R * 4.0 * std::numbers::pi * 0.5;
    const Imath::V3d w = direction(0.9, 0.4);
    for (double d : {1.5 * R, 3.0 * R}) {
        const Imath::V3d p = f.centre + w * d;
        const Imath::V3d n = (-w + Imath::V3d(0.2, 0.0, 0.0)).normalized();
        EXPECT_NEAR(lookup.irradiance(p, n).x, intensity * n.dot(-w) / (d * d), 1e-3 * intensity / (d * d));
        EXPECT_EQ(lookup.irradiance(p, w), Imath::V3d(0.0));
        // The cube-map form holds the same irradiance in the one texel toward the centre.
        const std::vector<Imath::V3f> map = lookup.incidentRadiance(p);
        const std::uint32_t texel = lookup.mapLayout().lookup(Imath::V3f(-w));
        EXPECT_NEAR(map[texel].x * lookup.mapLayout().solidAngle(texel), intensity / (d * d), 1e-4 * intensity / (d * d));
    }
}

TEST(ShadowFieldLookup, InsideTheInnerShellIsTheInnerShell) {
    const ShadowField f = test::uniformShadowField([](std::uint32_t shell, std::uint64_t m) { return shell + 0.001 * m; });
    const ShadowFieldLookup lookup(f);
    const Imath::V3d w = direction(0.3, 2.2);
    EXPECT_EQ(lookup.incidentRadiance(f.centre + w * (0.5 * f.radii.front())),
              lookup.incidentRadiance(f.centre + w * f.radii.front()));
}

TEST(ShadowFieldLookup, NonFinitePointsAreRefused) {
    const ShadowField f = test::uniformShadowField([](std::uint32_t, std::uint64_t) { return 1.0; });
    const ShadowFieldLookup lookup(f);
    EXPECT_THROW(lookup.irradiance(Imath::V3d(NAN, 0, 0), Imath::V3d(0, 1, 0)), Error);
}

}  // namespace
}  // namespace opal
