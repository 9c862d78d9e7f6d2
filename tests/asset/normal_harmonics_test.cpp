// The split of E into the normal harmonics and a residual (schema/asset/normal_harmonics.h).
#include "schema/asset/normal_harmonics.h"
#include "tests/asset/test_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace opal {
namespace {

std::vector<SurfaceSample> sphereSamples(std::size_t n, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> g;
    std::vector<SurfaceSample> samples(n);
    for (SurfaceSample& s : samples) {
        const Imath::V3f v(g(rng), g(rng), g(rng));
        s.normal = v.normalized();
        s.position = s.normal;
        s.area = 1.0f;
    }
    return samples;
}

// The nine functions as written out: a closed form the table must match.
TEST(NormalHarmonics, AreTheNineQuadraticsOfTheNormal) {
    const Imath::V3f n = Imath::V3f(0.3f, -0.5f, 0.8f).normalized();
    const std::array<float, 9> y = normalHarmonics(n);
    const float expected[9] = {1.0f,      n.x,       n.y,       n.z, n.x * n.y, n.y * n.z, 3 * n.z * n.z - 1,
                               n.x * n.z, n.x * n.x - n.y * n.y};
    for (int q = 0; q < 9; ++q) EXPECT_FLOAT_EQ(y[q], expected[q]) << "q = " << q;
}

// Values that are a combination of the nine come back as that combination, residual 0;
// a residual is orthogonal to every Y_q (least squares' normal equations).
TEST(HarmonicFit, RecoversACombinationAndLeavesAnOrthogonalResidual) {
    const std::vector<SurfaceSample> samples = sphereSamples(2000, 3);
    const HarmonicFit fit(samples);
    const std::size_t C = 2;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<float> a(9 * C);
    for (float& v : a) v = u(rng);
    std::vector<float> values(samples.size() * C), noisy(values.size());
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const std::array<float, 9> y = normalHarmonics(samples[i].normal);
        for (std::size_t c = 0; c < C; ++c) {
            double sum = 0.0;
            for (int q = 0; q < 9; ++q) sum += double(a[q * C + c]) * y[q];
            values[i * C + c] = float(sum);
            noisy[i * C + c] = float(sum) + std::pow(samples[i].normal.x, 5.0f) * (c + 1.0f);  // outside the span
        }
    }
    const std::vector<float> fitted = fit.coefficients(values, C);
    for (std::size_t j = 0; j < a.size(); ++j) EXPECT_NEAR(fitted[j], a[j], 1e-5) << j;
    std::vector<float> residual(values.size());
    fit.residual(values, C, fitted, residual, C);
    for (float r : residual) EXPECT_NEAR(r, 0.0f, 1e-5);

    fit.residual(noisy, C, fit.coefficients(noisy, C), residual, C);
    for (int q = 0; q < 9; ++q)
        for (std::size_t c = 0; c < C; ++c) {
            double dot = 0.0, norm = 0.0;
            for (std::size_t i = 0; i < samples.size(); ++i) {
                dot += double(fit.patterns()[i * 9 + q]) * residual[i * C + c];
                norm += std::abs(double(residual[i * C + c]));
            }
            EXPECT_LE(std::abs(dot), 1e-5 * norm) << "q = " << q << ", c = " << c;
        }
}

// A flat patch (every normal the same) cannot tell the nine apart: the fit still splits a
// constant exactly, with finite coefficients.
TEST(HarmonicFit, AFlatPatchSplitsAConstantExactly) {
    std::vector<SurfaceSample> samples(64);
    for (std::size_t i = 0; i < samples.size(); ++i) samples[i] = {Imath::V3f(float(i), 0, 0), Imath::V3f(0, 0, 1), 1.0f};
    const HarmonicFit fit(samples);
    const std::vector<float> values(samples.size(), 2.5f);
    const std::vector<float> a = fit.coefficients(values, 1);
    for (float v : a) EXPECT_TRUE(std::isfinite(v));
    std::vector<float> residual(values.size());
    fit.residual(values, 1, a, residual, 1);
    for (float r : residual) EXPECT_NEAR(r, 0.0f, 1e-5);
}

TEST(HarmonicFit, MismatchedSizesAreNamed) {
    const HarmonicFit fit(sphereSamples(10, 1));
    const std::vector<float> values(21);
    test::expectContains(test::errorOf([&] { fit.coefficients(values, 2); }), {"21 values for 10 samples of 2 channels"});
    std::vector<float> out(5);
    test::expectContains(test::errorOf([&] { fit.residual(std::vector<float>(10), 1, std::vector<float>(9), out, 1); }),
                         {"does not fit 10 samples"});
}

}  // namespace
}  // namespace opal
