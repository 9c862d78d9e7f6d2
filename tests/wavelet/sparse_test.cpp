#include "schema/wavelet/sparse.h"

#include "tests/wavelet/wavelet_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace opal {
namespace {

using Indices = std::vector<std::uint32_t>;

// Reference: all nonzero-score indices fully sorted by score (descending, then by index).
Indices rankByScore(const std::vector<double>& score) {
    Indices order;
    for (std::uint32_t i = 0; i < score.size(); ++i)
        if (score[i] > 0) order.push_back(i);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return score[a] > score[b] || (score[a] == score[b] && a < b);
    });
    return order;
}

Indices sorted(Indices v) {
    std::sort(v.begin(), v.end());
    return v;
}

// Random values on a coarse grid of levels, so that ties and zeros are frequent.
std::vector<float> quantizedRandom(std::size_t n, std::uint32_t seed) {
    std::vector<float> v = test::randomValues<float>(n, seed);
    for (float& x : v) x = std::round(x * 20.0f) / 4.0f;
    return v;
}

void expectValuesMatch(const SparseVector& kept, const std::vector<float>& dense) {
    ASSERT_EQ(kept.indices.size(), kept.values.size());
    for (std::size_t k = 0; k < kept.size(); ++k) EXPECT_EQ(kept.values[k], dense[kept.indices[k]]);
}

TEST(KeepLargest, PicksLargestMagnitudesInIndexOrder) {
    const std::vector<float> dense = {0.5f, -3.0f, 1.0f, 2.0f, -0.25f};
    const SparseVector kept = keepLargest(dense, 3);
    EXPECT_EQ(kept.indices, (Indices{1, 2, 3}));
    EXPECT_EQ(kept.values, (std::vector<float>{-3.0f, 1.0f, 2.0f}));
}

TEST(KeepLargest, BreaksTiesByLowerIndex) {
    const std::vector<float> dense = {1.0f, -2.0f, 2.0f, -1.0f, 2.0f, 1.0f};
    EXPECT_EQ(keepLargest(dense, 2).indices, (Indices{1, 2}));
    EXPECT_EQ(keepLargest(dense, 4).indices, (Indices{0, 1, 2, 4}));
}

TEST(KeepLargest, EdgeCases) {
    const std::vector<float> dense = {0.0f, 3.0f, 0.0f, -1.0f};
    EXPECT_EQ(keepLargest(dense, 0).size(), 0u);
    EXPECT_EQ(keepLargest(dense, 10).indices, (Indices{1, 3}));  // zeros are never kept
    EXPECT_EQ(keepLargest(std::vector<float>{}, 3).size(), 0u);
    EXPECT_EQ(keepLargest(std::vector<float>(5, 0.0f), 3).size(), 0u);
}

TEST(KeepLargest, MatchesAFullSort) {
    const std::vector<float> dense = quantizedRandom(3000, 41);
    std::vector<double> magnitude(dense.size());
    for (std::size_t i = 0; i < dense.size(); ++i) magnitude[i] = std::abs(dense[i]);
    const Indices ranked = rankByScore(magnitude);
    for (std::size_t n : {1u, 7u, 30u, 500u, 2000u, 5000u}) {
        const SparseVector kept = keepLargest(dense, n);
        const std::size_t count = std::min(n, ranked.size());
        EXPECT_EQ(kept.indices, sorted(Indices(ranked.begin(), ranked.begin() + count))) << n;
        expectValuesMatch(kept, dense);
    }
}

TEST(KeepLargest, RejectsNonFiniteValues) {
    test::expectErrorContaining(
        [] {
            keepLargest(std::vector<float>{1.0f, std::numeric_limits<float>::quiet_NaN()}, 1);
        },
        "keepLargest: coefficient 1 is not finite");
}

TEST(KeepEnergyFraction, ZeroKeepsNoneAndOneKeepsAllNonzeros) {
    const std::vector<float> dense = {0.0f, 1e-20f, -2.0f, 0.0f, 3.0f};
    EXPECT_EQ(keepEnergyFraction(dense, 0.0).size(), 0u);
    // 1e-20 squares to a float underflow, but energies are computed in double: kept.
    EXPECT_EQ(keepEnergyFraction(dense, 1.0).indices, (Indices{1, 2, 4}));
    EXPECT_EQ(keepEnergyFraction(std::vector<float>{}, 0.5).size(), 0u);
    EXPECT_EQ(keepEnergyFraction(std::vector<float>(4, 0.0f), 1.0).size(), 0u);
}

TEST(KeepEnergyFraction, KeepsTheFewestReachingTheFraction) {
    // Energies 9, 4, 1, 1 (total 15): 9 / 15 = 0.6; 13 / 15 = 0.8667; 14 / 15 = 0.9333.
    const std::vector<float> dense = {1.0f, -3.0f, 1.0f, 2.0f};
    EXPECT_EQ(keepEnergyFraction(dense, 0.6).indices, (Indices{1}));
    EXPECT_EQ(keepEnergyFraction(dense, 0.61).indices, (Indices{1, 3}));
    EXPECT_EQ(keepEnergyFraction(dense, 0.9).indices, (Indices{0, 1, 3}));  // tie: lower index
    EXPECT_EQ(keepEnergyFraction(dense, 0.95).indices, (Indices{0, 1, 2, 3}));
}

TEST(KeepEnergyFraction, WeighsCoefficientsByTheirNorms) {
    const std::vector<float> dense = {3.0f, 2.0f};
    const std::vector<float> norms = {0.1f, 1.0f};  // energies 0.9 and 4
    EXPECT_EQ(keepEnergyFraction(dense, 0.5).indices, (Indices{0}));
    EXPECT_EQ(keepEnergyFraction(dense, 0.5, norms).indices, (Indices{1}));
    // A zero norm means no energy: never kept, even at fraction 1.
    EXPECT_EQ(keepEnergyFraction(dense, 1.0, std::vector<float>{0.0f, 1.0f}).indices, (Indices{1}));
}

TEST(KeepEnergyFraction, MatchesAFullSort) {
    // Large enough for the selection's halving phase; ties from the quantized values.
    const std::vector<float> dense = quantizedRandom(5000, 43);
    std::vector<float> norms = test::randomValues<float>(dense.size(), 44);
    for (float& g : norms) g = std::round((g + 1.5f) * 4.0f) / 4.0f;
    std::vector<double> energy(dense.size());
    for (std::size_t i = 0; i < dense.size(); ++i)
        energy[i] = double(dense[i]) * dense[i] * norms[i];
    const Indices ranked = rankByScore(energy);
    const double total = std::accumulate(energy.begin(), energy.end(), 0.0);
    for (double fraction : {0.01, 0.3, 0.9, 0.95, 0.999, 1.0}) {
        std::size_t count = 0;
        for (double sum = 0; count < ranked.size() && (fraction == 1.0 || sum < fraction * total);
             ++count)
            sum += energy[ranked[count]];
        const SparseVector kept = keepEnergyFraction(dense, fraction, norms);
        EXPECT_EQ(kept.indices, sorted(Indices(ranked.begin(), ranked.begin() + count)))
            << fraction;
        expectValuesMatch(kept, dense);
    }
}

TEST(KeepEnergyFraction, RejectsBadInput) {
    const std::vector<float> dense = {1.0f, 2.0f};
    test::expectErrorContaining([&] { keepEnergyFraction(dense, 1.5); },
                                "fraction 1.500000 is not in [0, 1]");
    EXPECT_THROW(keepEnergyFraction(dense, -0.1), Error);
    EXPECT_THROW(keepEnergyFraction(dense, std::nan("")), Error);
    test::expectErrorContaining([&] { keepEnergyFraction(dense, 0.5, std::vector<float>{1.0f}); },
                                "1 norms for 2 coefficients");
    test::expectErrorContaining(
        [&] {
            keepEnergyFraction(dense, 0.5, std::vector<float>{1.0f, -1.0f});
        },
        "norm 1 is negative");
    EXPECT_THROW(keepEnergyFraction(std::vector<float>{INFINITY}, 0.5), Error);
}

}  // namespace
}  // namespace opal
