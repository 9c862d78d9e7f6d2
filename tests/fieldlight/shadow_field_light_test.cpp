// ShadowFieldLight (delegate/relight/shadow_field_light.h) against the analytic irradiance of
// a uniformly emitting sphere, through the light's transform; and its distance-aware
// visibility: blockers between the sample and the emitter shadow it, blockers beyond the
// emitter (the far rim of a melted candle) do not.
#include "tests/fieldlight/field_fixture.h"

#include "raytrace/ray_scene.h"
#include "schema/error.h"

#include <gtest/gtest.h>

#include <Imath/ImathMatrixAlgo.h>

#include <cmath>
#include <numbers>
#include <random>

namespace opal {
namespace {

using test::kEmitterRadiance;
using test::kEmitterRadius;
using test::sphereField;

// E = mu_eff E_perp, the irradiance the arrival stands for.
Imath::V3d irradianceOf(const LightArrival& a) { return Imath::V3d(a.irradiance) * double(a.cosTheta); }

PlacedSamples oneSample(const Imath::V3d& p, const Imath::V3d& n) {
    PlacedSamples s;
    s.positions.emplace_back(p);
    s.normals.emplace_back(n.normalized());
    return s;
}

// Rotation about an axis, then uniform scale, then translation (row vectors).
Imath::M44d placement(double scale, const Imath::V3d& axis, double angle, const Imath::V3d& at) {
    Imath::M44d r;
    r.setAxisAngle(axis.normalized(), angle);
    Imath::M44d s;
    s.setScale(scale);
    Imath::M44d t;
    t.setTranslation(at);
    return s * r * t;
}

TEST(ShadowFieldLight, SphereMatchesAnalyticIrradianceThroughItsTransform) {
    const double scale = 1.5, intensity = 2.0;
    const Imath::V3d at(10.0, -4.0, 7.0);
    const ShadowFieldLight light(sphereField().loaded,
                                 test::fieldLightDesc(placement(scale, {1.0, 2.0, 0.5}, 0.7, at), intensity));
    const double a = kEmitterRadius * scale;
    EXPECT_NEAR(light.emitterRadius(), a, 1e-3 * a);
    EXPECT_NEAR((light.centre() - at).length(), 0.0, 1e-9);
    const std::vector<double>& radii = sphereField().loaded->field.radii;
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double worst = 0.0;
    for (int i = 0; i < 300; ++i) {
        // From just outside the inner shell to twice the outer one (the far field too).
        const double d = scale * radii.front() * 1.02 * std::pow(2.0 * radii.back() / radii.front(), u(random));
        const double z = 2.0 * u(random) - 1.0, phi = 2.0 * std::numbers::pi * u(random);
        const Imath::V3d out(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z);
        const double theta = (std::numbers::pi / 2 - std::asin(a / d)) * u(random);
        const Imath::V3d side = out.cross(Imath::V3d(0.3, 0.9, -0.2)).normalized();
        const Imath::V3d normal = -out * std::cos(theta) + side * std::sin(theta);
        const std::vector<LightArrival> arrivals = light.arrivals(oneSample(at + out * d, normal), nullptr, 0.0f);
        const Imath::V3d e = irradianceOf(arrivals[0]);
        for (int c = 0; c < 3; ++c) {
            const double truth = intensity * test::sphereIrradiance(kEmitterRadiance[c], a, d, std::cos(theta));
            const double error = std::abs(e[c] / truth - 1.0);
            worst = std::max(worst, error);
            EXPECT_LT(error, 0.04) << "d " << d << " theta " << theta << " channel " << c;
        }
        EXPECT_GT(arrivals[0].cosTheta, 0.0f);
        EXPECT_LE(arrivals[0].cosTheta, 1.0f);
    }
    std::printf("worst relative error against pi L (a/d)^2 cos theta: %.4f\n", worst);
}

TEST(ShadowFieldLight, FacingAwayReceivesNothing) {
    const ShadowFieldLight light(sphereField().loaded, test::fieldLightDesc(Imath::M44d()));
    // Nothing but the compressed maps' ringing near the horizon: never negative, and below a
    // millionth of what the same point gets facing the emitter.
    for (double d : {3.0, 8.0, 40.0}) {
        const Imath::V3d away =
            irradianceOf(light.arrivals(oneSample({d, 0.0, 0.0}, {1.0, 0.0, 0.0}), nullptr, 0.0f)[0]);
        const Imath::V3d facing =
            irradianceOf(light.arrivals(oneSample({d, 0.0, 0.0}, {-1.0, 0.0, 0.0}), nullptr, 0.0f)[0]);
        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(away[c], 0.0) << d;
            EXPECT_LT(away[c], 1e-6 * facing[c]) << d;
        }
    }
}

// A sample 4 emitter radii below the emitter, facing up; a large square blocker at a height.
Imath::V3d shadowedBy(const RayScene* scene) {
    const ShadowFieldLight light(sphereField().loaded, test::fieldLightDesc(test::translation(0.0, 8.0, 0.0)));
    return irradianceOf(light.arrivals(oneSample({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}), scene, 1e-4f)[0]);
}

TEST(ShadowFieldLight, BlockersShadowOnlyBetweenSampleAndEmitter) {
    const Imath::V3d open = shadowedBy(nullptr);
    ASSERT_GT(open.x, 0.0);
    RayScene between;
    between.addMesh(test::rectangleY(4.0, -20.0, 20.0, -20.0, 20.0), Imath::M44d());
    between.commit();
    EXPECT_EQ(shadowedBy(&between), Imath::V3d(0.0));
    // Beyond the emitter (above it, and through the top of its bounding sphere's shell
    // region but past the emitter): no shadow at all, bit for bit the open value.
    RayScene beyond;
    beyond.addMesh(test::rectangleY(8.0 + 1.5 * kEmitterRadius, -20.0, 20.0, -20.0, 20.0), Imath::M44d());
    beyond.commit();
    EXPECT_EQ(shadowedBy(&beyond), open);
    // Half the sky between: a half-plane through the line under the emitter's centre blocks
    // about half the light.
    RayScene half;
    half.addMesh(test::rectangleY(4.0, 0.0, 20.0, -20.0, 20.0), Imath::M44d());
    half.commit();
    const Imath::V3d e = shadowedBy(&half);
    EXPECT_GT(e.x, 0.3 * open.x);
    EXPECT_LT(e.x, 0.7 * open.x);
}

// An open tube (a melted candle's rim, inner radius R) around the emitter: a sample on the
// inner wall facing the axis sees the emitter; the wall opposite lies beyond it.
RenderMesh tube(double radius, double height, int segments) {
    RenderMesh mesh;
    for (int i = 0; i < segments; ++i) {
        const double phi = 2.0 * std::numbers::pi * i / segments;
        mesh.points.emplace_back(float(radius * std::cos(phi)), 0.0f, float(radius * std::sin(phi)));
        mesh.points.emplace_back(float(radius * std::cos(phi)), float(height), float(radius * std::sin(phi)));
    }
    for (int i = 0; i < segments; ++i) {
        const int j = (i + 1) % segments;
        mesh.faceVertexCounts.push_back(4);
        for (int v : {2 * i, 2 * j, 2 * j + 1, 2 * i + 1}) mesh.faceVertexIndices.push_back(v);
    }
    return mesh;
}

TEST(ShadowFieldLight, EmitterInsideAConcavityLightsTheInnerWall) {
    const double radius = 4.0 * kEmitterRadius, height = 6.0 * kEmitterRadius, flameHeight = 4.0 * kEmitterRadius;
    const int segments = 48;
    RayScene cup;
    cup.addMesh(tube(radius, height, segments), Imath::M44d());
    cup.commit();
    const ShadowFieldLight light(sphereField().loaded,
                                 test::fieldLightDesc(test::translation(0.0, flameHeight, 0.0)));
    // The middle of a wall face at the flame's height, facing the axis.
    const double phi = std::numbers::pi / segments, inner = radius * std::cos(std::numbers::pi / segments);
    const Imath::V3d p(inner * std::cos(phi), flameHeight, inner * std::sin(phi));
    const Imath::V3d n = -Imath::V3d(std::cos(phi), 0.0, std::sin(phi));
    // A direction-only visibility would count the opposite wall as a blocker:
    EXPECT_TRUE(cup.occluded(Ray(Imath::V3f(p + n * 1e-3), Imath::V3f(n), 0.0f, 1e30f)));
    const Imath::V3d open = irradianceOf(light.arrivals(oneSample(p, n), nullptr, 0.0f)[0]);
    const Imath::V3d inCup = irradianceOf(light.arrivals(oneSample(p, n), &cup, 1e-3f)[0]);
    ASSERT_GT(open.x, 0.0);
    EXPECT_EQ(inCup, open);
    const double truth = test::sphereIrradiance(kEmitterRadiance[0], kEmitterRadius, inner, 1.0);
    EXPECT_NEAR(inCup.x / truth, 1.0, 0.04);
}

TEST(ShadowFieldLight, RejectsBadTransformsAndEmission) {
    hd::LightDesc desc = test::fieldLightDesc(Imath::M44d());
    desc.transform[0][0] = 2.0;  // non-uniform scale
    EXPECT_THROW(ShadowFieldLight(sphereField().loaded, desc), Error);
    desc = test::fieldLightDesc(Imath::M44d(), -1.0);
    EXPECT_THROW(ShadowFieldLight(sphereField().loaded, desc), Error);
    EXPECT_THROW(ShadowFieldLight(nullptr, test::fieldLightDesc(Imath::M44d())), Error);
}

}  // namespace
}  // namespace opal
