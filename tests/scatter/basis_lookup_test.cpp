// BasisLookup's batched evaluation (the bake's inner loop) against its one-radius form:
// the same bits for every radius, including those outside the table (beyond rMax,
// negative, NaN), for K that is and is not a multiple of the four-wide SIMD blocks.
#include "schema/scatter/profile_basis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace opal {
namespace {

// K smooth, signed functions on [0, rMax] sampled at L radii: enough structure for the
// table's interpolation to matter.
ProfileBasis syntheticBasis(int K, double rMax) {
    const int L = 97;
    std::vector<double> radii(L), weights(L, 1.0), values(std::size_t(K) * L);
    for (int l = 0; l < L; ++l) radii[l] = rMax * std::pow(double(l) / (L - 1), 2.0);
    for (int k = 0; k < K; ++k)
        for (int l = 0; l < L; ++l)
            values[std::size_t(k) * L + l] = std::exp(-radii[l] / (1.0 + k)) * std::cos(0.3 * k * radii[l]) - 0.01 * k;
    return ProfileBasis(radii, weights, values, std::vector<double>(K, 1.0), EditableRange::coveringPresets());
}

std::vector<float> testRadii(float rMax, std::size_t count) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> uniform(0.0f, 1.2f * rMax);
    std::vector<float> r(count);
    for (float& x : r) x = uniform(rng);
    const float special[] = {0.0f, -0.0f, rMax, std::nextafter(rMax, 0.0f), std::nextafter(rMax, 2 * rMax), -1.0f,
                             std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                             1e-30f, std::numeric_limits<float>::denorm_min()};
    for (std::size_t j = 0; j < std::size(special) && j * 3 < count; ++j) r[j * 3] = special[j];
    return r;
}

TEST(BasisLookup, WeightedBatchMatchesOneRadiusEvaluationBitForBit) {
    for (int K : {1, 3, 4, 5, 12, 13}) {
        const BasisLookup lookup(syntheticBasis(K, 40.0), 512);
        const std::size_t count = 103;  // not a multiple of 4: the scalar tail runs too
        const std::vector<float> r = testRadii(lookup.rMax(), count);
        std::vector<float> weight(count);
        for (std::size_t j = 0; j < count; ++j) weight[j] = 0.5f + 0.01f * float(j);
        const std::size_t stride = count + 5;
        std::vector<float> rows(std::size_t(K) * stride, -7.0f);
        lookup.evaluateWeighted(r, weight, rows.data(), stride);
        std::vector<float> b(K);
        for (std::size_t j = 0; j < count; ++j) {
            lookup.evaluate(r[j], b.data());
            for (int k = 0; k < K; ++k) {
                const float expected = b[k] * weight[j];
                ASSERT_EQ(std::memcmp(&rows[k * stride + j], &expected, sizeof(float)), 0)
                    << "K " << K << " k " << k << " r " << r[j] << ": " << rows[k * stride + j] << " vs " << expected;
            }
        }
        for (int k = 0; k < K; ++k)  // the gap between rows is left alone
            for (std::size_t j = count; j < stride; ++j) ASSERT_EQ(rows[k * stride + j], -7.0f);
    }
}

TEST(BasisLookup, MatchesTheBasisWithinInterpolationError) {
    const ProfileBasis basis = syntheticBasis(5, 40.0);
    const BasisLookup lookup(basis);
    float b[5];
    for (double r : {0.0, 0.01, 0.5, 3.0, 17.0, 39.9}) {
        lookup.evaluate(float(r), b);
        for (int k = 0; k < 5; ++k) EXPECT_NEAR(b[k], basis.evaluate(k, r), 2e-4) << "k " << k << " r " << r;
    }
    lookup.evaluate(41.0f, b);
    for (int k = 0; k < 5; ++k) EXPECT_EQ(b[k], 0.0f);
}

}  // namespace
}  // namespace opal
