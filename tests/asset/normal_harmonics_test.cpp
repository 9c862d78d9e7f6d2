// The split of E into the normal harmonics and a residual (schema/asset/normal_harmonics.h).
#include "schema/asset/normal_harmonics.h"
#include "tests/asset/test_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
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

// The 36 as written out: the nine times 1, x', y', z' of the position in the set's frame,
// the frame being the samples' bounding box (centre, half the largest extent).
TEST(HarmonicSet, AreTheNineTimesThePositionInTheSamplesFrame) {
    const std::vector<SurfaceSample> samples = {{Imath::V3f(-1, 2, 0), Imath::V3f(0, 0, 1), 1.0f},
                                                {Imath::V3f(3, 4, 1), Imath::V3f(1, 0, 0), 1.0f}};
    const HarmonicSet set = harmonicSetFor(samples);
    EXPECT_EQ(set.count, 36u);
    EXPECT_EQ(set.centre, Imath::V3f(1, 3, 0.5f));
    EXPECT_FLOAT_EQ(set.inverseScale, 0.5f);  // half of the largest extent, 4, is 2
    const SurfaceSample x{Imath::V3f(2, 1, -1), Imath::V3f(0.3f, -0.5f, 0.8f).normalized(), 1.0f};
    std::array<float, 36> f;
    harmonicValues(set, x, f);
    const std::array<float, 9> y = normalHarmonics(x.normal);
    const float p[4] = {1.0f, (2 - 1) * 0.5f, (1 - 3) * 0.5f, (-1 - 0.5f) * 0.5f};
    for (int b = 0; b < 4; ++b)
        for (int h = 0; h < 9; ++h) EXPECT_FLOAT_EQ(f[b * 9 + h], y[h] * p[b]) << "b = " << b << ", h = " << h;
    std::array<float, 9> nine;
    harmonicValues(HarmonicSet{9}, x, nine);
    for (int h = 0; h < 9; ++h) EXPECT_EQ(nine[h], y[h]);
    test::expectContains(test::errorOf([&] { harmonicValues(HarmonicSet{12}, x, std::span<float>(f.data(), 12)); }),
                         {"12 functions (9 or 36)"});
    test::expectContains(test::errorOf([&] { HarmonicFit(samples, HarmonicSet{10}); }), {"10 functions, expected 9 or 36"});
}

// Samples with normals and positions that vary independently (a random cloud): both sets
// are of full rank on them.
std::vector<SurfaceSample> cloudSamples(std::size_t n, std::uint32_t seed) {
    std::vector<SurfaceSample> samples = sphereSamples(n, seed);
    std::mt19937 rng(seed + 1);
    std::uniform_real_distribution<float> u(-5.0f, 5.0f);
    for (SurfaceSample& s : samples) s.position = Imath::V3f(u(rng), u(rng) + 10.0f, u(rng));
    return samples;
}

// Values that are a combination of the set's functions come back as that combination,
// residual 0; a residual is orthogonal to every f_q (least squares' normal equations).
void expectRecoversACombination(const std::vector<SurfaceSample>& samples, const HarmonicSet& set,
                                std::size_t C = 2) {
    SCOPED_TRACE(std::to_string(set.count) + " functions, " + std::to_string(C) + " channels");
    const HarmonicFit fit(samples, set);
    const std::size_t Q = set.count;
    ASSERT_EQ(fit.count(), Q);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<float> a(Q * C);
    for (float& v : a) v = u(rng);
    std::vector<float> values(samples.size() * C), noisy(values.size());
    std::vector<float> f(Q);
    for (std::size_t i = 0; i < samples.size(); ++i) {
        harmonicValues(set, samples[i], f);
        for (std::size_t c = 0; c < C; ++c) {
            double sum = 0.0;
            for (std::size_t q = 0; q < Q; ++q) sum += double(a[q * C + c]) * f[q];
            values[i * C + c] = float(sum);
            noisy[i * C + c] = float(sum) + std::pow(samples[i].normal.x, 5.0f) * (c + 1.0f);  // outside the span
        }
    }
    const std::vector<float> fitted = fit.coefficients(values, C);
    for (std::size_t j = 0; j < a.size(); ++j) EXPECT_NEAR(fitted[j], a[j], 1e-4) << j;
    std::vector<float> residual(values.size());
    fit.residual(values, C, fitted, residual, C);
    for (float r : residual) EXPECT_NEAR(r, 0.0f, 1e-4);

    fit.residual(noisy, C, fit.coefficients(noisy, C), residual, C);
    for (std::size_t q = 0; q < Q; ++q)
        for (std::size_t c = 0; c < C; ++c) {
            double dot = 0.0, norm = 0.0;
            for (std::size_t i = 0; i < samples.size(); ++i) {
                dot += double(fit.patterns()[i * Q + q]) * residual[i * C + c];
                norm += std::abs(double(residual[i * C + c]));
            }
            EXPECT_LE(std::abs(dot), 1e-5 * norm) << "q = " << q << ", c = " << c;
        }
}

TEST(HarmonicFit, RecoversACombinationAndLeavesAnOrthogonalResidual) {
    expectRecoversACombination(sphereSamples(2000, 3), HarmonicSet{9});
    const std::vector<SurfaceSample> cloud = cloudSamples(2000, 3);
    expectRecoversACombination(cloud, harmonicSetFor(cloud));
}

// The channel counts a light edit fits (three per Fresnel moment) take their own loops, and
// any other count Eigen's; over several blocks of samples with a part-filled last one.
TEST(HarmonicFit, RecoversACombinationInEveryChannelCount) {
    const std::vector<SurfaceSample> sphere = sphereSamples(5000, 4), cloud = cloudSamples(5000, 4);
    for (const std::size_t C : {1, 3, 5, 6, 12}) {
        expectRecoversACombination(sphere, HarmonicSet{9}, C);
        expectRecoversACombination(cloud, harmonicSetFor(cloud), C);
    }
}

// A flat patch (every normal the same) cannot tell the functions apart: the fit still
// splits a constant exactly, with finite coefficients.
TEST(HarmonicFit, AFlatPatchSplitsAConstantExactly) {
    std::vector<SurfaceSample> samples(64);
    for (std::size_t i = 0; i < samples.size(); ++i) samples[i] = {Imath::V3f(float(i), 0, 0), Imath::V3f(0, 0, 1), 1.0f};
    for (const HarmonicSet& set : {HarmonicSet{9}, harmonicSetFor(samples)}) {
        const HarmonicFit fit(samples, set);
        const std::vector<float> values(samples.size(), 2.5f);
        const std::vector<float> a = fit.coefficients(values, 1);
        for (float v : a) EXPECT_TRUE(std::isfinite(v));
        std::vector<float> residual(values.size());
        fit.residual(values, 1, a, residual, 1);
        for (float r : residual) EXPECT_NEAR(r, 0.0f, 1e-5) << set.count;
    }
}

TEST(HarmonicFit, MismatchedSizesAreNamed) {
    const HarmonicFit fit(sphereSamples(10, 1), HarmonicSet{9});
    const std::vector<float> values(21);
    test::expectContains(test::errorOf([&] { fit.coefficients(values, 2); }), {"21 values for 10 samples of 2 channels"});
    std::vector<float> out(5);
    test::expectContains(test::errorOf([&] { fit.residual(std::vector<float>(10), 1, std::vector<float>(9), out, 1); }),
                         {"does not fit 10 samples"});
}

}  // namespace
}  // namespace opal
