#include "delegate/relight/dome_convolution.h"

#include "schema/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>

namespace opal {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<float> cubeOf(const CubeMapLayout& cube, const std::function<Imath::V3f(const Imath::V3f&)>& f) {
    std::vector<float> rgb;
    for (std::uint32_t t = 0; t < cube.texels(); ++t) {
        const Imath::V3f v = f(cube.direction(t));
        rgb.insert(rgb.end(), {v.x, v.y, v.z});
    }
    return rgb;
}

Imath::V3f randomNormal(std::mt19937& rng) {
    std::normal_distribution<float> g;
    for (;;) {
        const Imath::V3f v(g(rng), g(rng), g(rng));
        if (v.length() > 1e-3f) return v.normalized();
    }
}

// L(w) = a + b.w over the hemisphere around n: the tangential part of b.w integrates to 0,
// so U_m = 2 pi (a int_0^1 mu P_m dmu + b.n int_0^1 mu^2 P_m dmu).
double linearSkyMoment(FresnelBasis basis, int m, double a, double bn) {
    // {int mu P_m, int mu^2 P_m} on [0, 1]: Schlick P = 1, (1 - mu)^5, (1 - mu)^2 (Beta
    // functions); Legendre P = 1, 2 mu - 1, 6 mu^2 - 6 mu + 1.
    static constexpr double schlick[3][2] = {{1.0 / 2, 1.0 / 3}, {1.0 / 42, 1.0 / 168}, {1.0 / 12, 1.0 / 30}};
    static constexpr double legendre[3][2] = {{1.0 / 2, 1.0 / 3}, {1.0 / 6, 1.0 / 6}, {0.0, 1.0 / 30}};
    const auto& k = basis == FresnelBasis::Schlick ? schlick[m] : legendre[m];
    return 2.0 * kPi * (a * k[0] + bn * k[1]);
}

TEST(DomeConvolution, LinearSkyGivesClosedFormMoments) {
    const double a = 2.0;
    const Imath::V3f b(0.5f, 0.8f, -0.3f);
    const CubeMapLayout cube(32);
    const auto radiance = cubeOf(cube, [&](const Imath::V3f& d) { return Imath::V3f(float(a + b.dot(d))); });
    std::mt19937 rng(5);
    for (FresnelBasis basis : {FresnelBasis::Schlick, FresnelBasis::Legendre}) {
        const DomeConvolution open(cube, radiance, 3, basis);
        for (int k = 0; k < 200; ++k) {
            const Imath::V3f n = randomNormal(rng);
            float u[9] = {};
            open.add(n, Imath::V3f(1.0f), u);
            for (int m = 0; m < 3; ++m) {
                const double expected = linearSkyMoment(basis, m, a, b.dot(n));
                // The cube map's texels straddle the horizon: about 0.3% of U_0.
                EXPECT_NEAR(u[3 * m], expected, 3e-3 * linearSkyMoment(basis, 0, a, b.dot(n)))
                    << "m " << m << " normal " << n << (basis == FresnelBasis::Schlick ? " Schlick" : " Legendre");
            }
        }
    }
}

// A bright sun over a sky: the grid's interpolation against the exact sum at the same normal.
TEST(DomeConvolution, InterpolationFollowsTheExactSum) {
    const CubeMapLayout cube(32);
    const Imath::V3f sun = Imath::V3f(0.3f, 0.8f, 0.5f).normalized();
    const auto radiance = cubeOf(cube, [&](const Imath::V3f& d) {
        const float sky = 0.2f + 0.8f * std::max(0.0f, d.y);
        return Imath::V3f(d.dot(sun) > 0.999f ? 2000.0f : sky, sky, 1.5f * sky);
    });
    const DomeConvolution open(cube, radiance, 2, FresnelBasis::Schlick);
    std::mt19937 rng(9);
    std::vector<double> errors;
    for (int k = 0; k < 2000; ++k) {
        const Imath::V3f n = randomNormal(rng);
        float u[6] = {};
        open.add(n, Imath::V3f(1.0f), u);
        const std::vector<float> exact = open.exact(n);
        for (int c = 0; c < 3; ++c) errors.push_back(std::abs(u[c] - exact[c]) / exact[c]);
    }
    std::sort(errors.begin(), errors.end());
    const double median = errors[errors.size() / 2], p95 = errors[errors.size() * 95 / 100];
    std::printf("[ dome convolution ] interpolated vs exact U_0: median %.3f%%, p95 %.3f%%, max %.2f%%\n",
                100 * median, 100 * p95, 100 * errors.back());
    EXPECT_LT(median, 2e-3);
    EXPECT_LT(p95, 1e-2);
}

TEST(DomeConvolution, RejectsMismatchedInput) {
    const CubeMapLayout cube(4);
    const std::vector<float> radiance(cube.texels() * 3, 1.0f);
    EXPECT_THROW(DomeConvolution(cube, std::span(radiance).first(30), 2, FresnelBasis::Schlick), Error);
    EXPECT_THROW(DomeConvolution(cube, radiance, 0, FresnelBasis::Schlick), Error);
    EXPECT_THROW(DomeConvolution(cube, radiance, 4, FresnelBasis::Schlick), Error);
    const DomeConvolution open(cube, radiance, 1, FresnelBasis::Schlick);
    float u[3] = {};
    open.add(Imath::V3f(0.0f), Imath::V3f(1.0f), u);  // not a direction: a finite value, no crash
    EXPECT_TRUE(std::isfinite(u[0]));
}

}  // namespace
}  // namespace opal
