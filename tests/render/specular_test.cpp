#include "delegate/image/specular.h"

#include "schema/scatter/dipole.h"

#include <gtest/gtest.h>

#include <random>

#include <cmath>
#include <numbers>

namespace opal {
namespace {

constexpr double kPi = std::numbers::pi;

// integral over the hemisphere of f_s(l, v) (n.l) dl, by a midpoint rule in (cos theta, phi).
double directionalAlbedo(double alpha, double eta, double cosView) {
    const Imath::V3d n(0, 0, 1), v(std::sqrt(1.0 - cosView * cosView), 0.0, cosView);
    const int thetas = 2000, phis = 400;
    double sum = 0.0;
    for (int i = 0; i < thetas; ++i) {
        // Dense near the normal, where a narrow lobe lives: mu = 1 - s^2.
        const double s0 = double(i) / thetas, s1 = double(i + 1) / thetas, s = 0.5 * (s0 + s1);
        const double mu = 1.0 - s * s, dmu = (1.0 - s0 * s0) - (1.0 - s1 * s1);
        for (int j = 0; j < phis; ++j) {
            const double phi = 2.0 * kPi * (j + 0.5) / phis;
            const double sinTheta = std::sqrt(std::max(0.0, 1.0 - mu * mu));
            const Imath::V3d l(sinTheta * std::cos(phi), sinTheta * std::sin(phi), mu);
            sum += ggxReflectance(n, v, l, alpha, eta) * dmu * (2.0 * kPi / phis);
        }
    }
    return sum;
}

TEST(Specular, DistributionIsNormalized) {
    for (double alpha : {0.05, 0.3, 0.8}) {
        // integral D(h) (n.h) dw_h = 2 pi integral D(mu) mu dmu.
        const int steps = 200000;
        double sum = 0.0;
        for (int i = 0; i < steps; ++i) {
            const double mu = (i + 0.5) / steps;
            sum += ggxDistribution(mu, alpha) * mu / steps;
        }
        EXPECT_NEAR(2.0 * kPi * sum, 1.0, 2e-3) << "alpha " << alpha;
    }
}

TEST(Specular, SmoothLobeReflectsTheFresnelFraction) {
    // A nearly smooth dielectric reflects F_r(eta, n.v) of the light; masking is negligible.
    const double eta = 1.4;
    const double albedo = directionalAlbedo(ggxAlpha(0.15), eta, 1.0);
    const double fr = fresnelReflectance(eta, 1.0);
    EXPECT_NEAR(fr, std::pow((eta - 1.0) / (eta + 1.0), 2.0), 1e-6);
    EXPECT_NEAR(albedo, fr, 0.03 * fr);
}

TEST(Specular, NeverCreatesEnergy) {
    for (double roughness : {0.1, 0.35, 0.7, 1.0})
        for (double cosView : {1.0, 0.5, 0.1}) {
            const double albedo = directionalAlbedo(ggxAlpha(roughness), 1.4, cosView);
            EXPECT_GT(albedo, 0.0);
            EXPECT_LE(albedo, fresnelReflectance(1.4, cosView) + 0.01) << roughness << " " << cosView;
        }
}

TEST(Specular, IsReciprocalAndZeroBelowTheHorizon) {
    const Imath::V3d n(0, 0, 1);
    const Imath::V3d a = Imath::V3d(0.3, 0.2, 0.9).normalized(), b = Imath::V3d(-0.5, 0.1, 0.6).normalized();
    const double alpha = ggxAlpha(0.4);
    // f(a, b) n.b / n.b == f(b, a) n.a / n.a
    EXPECT_NEAR(ggxReflectance(n, a, b, alpha, 1.3) / n.dot(b), ggxReflectance(n, b, a, alpha, 1.3) / n.dot(a), 1e-12);
    EXPECT_EQ(ggxReflectance(n, a, Imath::V3d(0.2, 0.0, -0.9).normalized(), alpha, 1.3), 0.0);
    EXPECT_EQ(ggxReflectance(n, Imath::V3d(0.2, 0.0, -0.9).normalized(), a, alpha, 1.3), 0.0);
}

TEST(Specular, TabulatedFresnelGivesTheSameLobe) {
    std::mt19937 rng(5);
    std::normal_distribution<double> normal;
    const auto unitVector = [&] { return Imath::V3d(normal(rng), normal(rng), normal(rng)).normalized(); };
    for (double eta : {1.0, 1.3, 1.8}) {
        const FresnelTable table(eta);
        for (int i = 0; i < 2000; ++i) {
            const Imath::V3d n = unitVector(), v = unitVector(), l = unitVector();
            const double exact = ggxReflectance(n, v, l, 0.12, eta), tabulated = ggxReflectance(n, v, l, 0.12, table);
            ASSERT_NEAR(tabulated, exact, 1e-5 * std::max(1.0, exact)) << "eta " << eta;
        }
    }
}

TEST(Specular, ReflectionAndFootprint) {
    const Imath::V3d n(0, 1, 0), v = Imath::V3d(1, 1, 0).normalized();
    const Imath::V3d r = reflect(v, n);
    EXPECT_NEAR(r.x, -v.x, 1e-12);
    EXPECT_NEAR(r.y, v.y, 1e-12);
    EXPECT_LT(reflectionFootprint(ggxAlpha(0.1)), reflectionFootprint(ggxAlpha(0.5)));
    EXPECT_LE(reflectionFootprint(ggxAlpha(1.0)), kPi);
    EXPECT_NEAR(fresnelReflectance(1.4, 0.0), 1.0, 1e-9);  // grazing: everything is reflected
}

}  // namespace
}  // namespace opal
