// The field of a uniformly emitting sphere against its analytic irradiance: a sphere of
// radiance L and radius a, seen from distance d by a surface whose normal is tilted by
// theta from the sphere's centre with theta + asin(a / d) <= 90 degrees (the sphere wholly
// above the horizon), gives E = pi L (a / d)^2 cos(theta). Baked at the shipped defaults.
#include "bake/light/emitter_shapes.h"
#include "bake/light/field_bake.h"
#include "bake/random.h"
#include "schema/asset/shadow_field_lookup.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace opal {
namespace {

constexpr double kRadius = 5.0;  // mm
const Imath::V3f kRadiance(2.0f, 1.0f, 0.5f);

ShadowField defaultSphereField() {
    FieldBakeStats stats;
    ShadowField f = bakeShadowField(sphereEmitter(kRadius, kRadiance), FieldSettings{}, nullptr, {}, &stats);
    std::printf("default sphere field: %.1f s, %llu rays, %llu coefficients, map error worst %.4f rms %.4f\n",
                stats.seconds, (unsigned long long)stats.rays, (unsigned long long)stats.coefficients,
                stats.worstMapError, stats.rmsMapError);
    return f;
}

Imath::V3d randomDirection(Random& random) {
    const double z = 2.0 * random.uniformDouble() - 1.0, phi = 2.0 * std::numbers::pi * random.uniformDouble();
    const double s = std::sqrt(1.0 - z * z);
    return {s * std::cos(phi), s * std::sin(phi), z};
}

// A unit vector at angle theta from `axis`.
Imath::V3d tilted(const Imath::V3d& axis, double theta, Random& random) {
    Imath::V3d side = axis.cross(randomDirection(random)).normalized();
    return axis * std::cos(theta) + side * std::sin(theta);
}

// One test case: ctest runs each case in its own process, and the default bake takes
// most of a minute on two cores.
TEST(SphereField, DefaultFieldReproducesAnalyticIrradiance) {
    const ShadowField f = defaultSphereField();
    EXPECT_EQ(f.shells(), 16u);
    EXPECT_EQ(f.directionsPerShell(), 6u * 16 * 16);
    EXPECT_EQ(f.mapTexels(), 6u * 32 * 32);
    EXPECT_NEAR(f.emitterRadius, kRadius, 1e-3);
    EXPECT_NEAR(f.radii.front(), 1.05 * f.emitterRadius, 1e-9);
    EXPECT_NEAR(f.radii.back(), 8.0 * f.emitterRadius, 1e-9);

    const ShadowFieldLookup lookup(f);
    Random random(7, 0);
    double worst = 0.0;
    for (int i = 0; i < 400; ++i) {
        // Radii from the inner shell to twice the outer one (the far field too).
        const double d = f.radii.front() * std::pow(2.0 * f.radii.back() / f.radii.front(), random.uniformDouble());
        const Imath::V3d toPoint = randomDirection(random);
        const double alpha = std::asin(kRadius / d);
        const double theta = (std::numbers::pi / 2 - alpha) * random.uniformDouble();
        const Imath::V3d normal = tilted(-toPoint, theta, random);
        const Imath::V3d e = lookup.irradiance(f.centre + toPoint * d, normal);
        const double analytic = std::numbers::pi * (kRadius / d) * (kRadius / d) * std::cos(theta);
        for (int c = 0; c < 3; ++c) {
            const double error = std::abs(e[c] / (analytic * kRadiance[c]) - 1.0);
            worst = std::max(worst, error);
            EXPECT_LT(error, 0.03) << "d " << d << " theta " << theta << " channel " << c;
        }
    }
    std::printf("worst relative irradiance error: %.4f\n", worst);

    // Facing away from the sphere: nothing but the compressed maps' ringing, never negative.
    for (double d : {1.2 * f.radii.front(), 0.5 * (f.radii.front() + f.radii.back()), 2.0 * f.radii.back()}) {
        const Imath::V3d away = lookup.irradiance(f.centre + Imath::V3d(d, 0.0, 0.0), Imath::V3d(1.0, 0.0, 0.0));
        const double facing = std::numbers::pi * (kRadius / d) * (kRadius / d);
        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(away[c], 0.0) << d;
            EXPECT_LT(away[c], 1e-6 * facing) << d;
        }
    }
}

}  // namespace
}  // namespace opal
