// keepLargest against a brute-force reference: every nonzero coefficient sorted by
// magnitude (descending, ties by lower index), the first n taken. Random vectors built to
// hit the selection's corner cases: many ties, many zeros (and -0), denormals (they share
// a histogram bin with zero), a wide dynamic range, and all values in one bin.
#include "schema/wavelet/sparse.h"

#include "tests/wavelet/wavelet_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace opal {
namespace {

using Indices = std::vector<std::uint32_t>;

Indices referenceLargest(const std::vector<float>& dense, std::size_t n) {
    Indices order;
    for (std::uint32_t i = 0; i < dense.size(); ++i)
        if (dense[i] != 0.0f) order.push_back(i);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return std::abs(dense[a]) > std::abs(dense[b]); });
    order.resize(std::min(n, order.size()));
    std::sort(order.begin(), order.end());
    return order;
}

enum class Kind { Ties, Zeros, Denormals, WideRange, OneBin };

std::vector<float> randomVector(Kind kind, std::size_t size, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::vector<float> v(size);
    for (float& x : v) {
        const double u = uniform(rng);
        switch (kind) {
        case Kind::Ties: x = float(std::round(u * 6.0) / 3.0); break;  // 13 levels
        case Kind::Zeros: x = std::abs(u) < 0.7 ? (u < 0 ? -0.0f : 0.0f) : float(u); break;
        case Kind::Denormals:
            x = std::abs(u) < 0.3 ? 0.0f : float(u * 1e-39) * (std::abs(u) > 0.9 ? 1e30f : 1.0f);
            break;
        case Kind::WideRange: x = float(std::copysign(std::exp(30.0 * u), u)); break;
        case Kind::OneBin: x = float(1.0 + 0.1 * std::abs(u)) * (u < 0 ? -1.0f : 1.0f); break;
        }
    }
    return v;
}

TEST(KeepLargestReference, MatchesASortOnRandomVectors) {
    const Kind kinds[] = {Kind::Ties, Kind::Zeros, Kind::Denormals, Kind::WideRange, Kind::OneBin};
    std::uint32_t seed = 1;
    for (Kind kind : kinds)
        for (std::size_t size : {1u, 2u, 3u, 7u, 64u, 1000u, 4097u}) {
            const std::vector<float> dense = randomVector(kind, size, seed++);
            const std::size_t nonZeros = std::size_t(std::count_if(dense.begin(), dense.end(), [](float x) { return x != 0.0f; }));
            for (std::size_t n : {std::size_t(0), std::size_t(1), size / 100 + 1, size / 10, size / 2,
                                  nonZeros > 0 ? nonZeros - 1 : 0, nonZeros, nonZeros + 1, size}) {
                const SparseVector kept = keepLargest(dense, n);
                ASSERT_EQ(kept.indices, referenceLargest(dense, n))
                    << "kind " << int(kind) << " size " << size << " n " << n;
                ASSERT_EQ(kept.values.size(), kept.indices.size());
                for (std::size_t j = 0; j < kept.size(); ++j)
                    EXPECT_EQ(std::bit_cast<std::uint32_t>(kept.values[j]),
                              std::bit_cast<std::uint32_t>(dense[kept.indices[j]]));
            }
        }
}

TEST(KeepLargestReference, MatchesASortAtBakeSize) {
    // One row of a 65,536-sample bake keeps 656; a Haar-like spread of magnitudes.
    std::vector<float> dense = randomVector(Kind::WideRange, 65536, 99);
    for (std::size_t i = 0; i < dense.size(); i += 7) dense[i] = 0.0f;
    for (std::size_t i = 3; i < dense.size(); i += 11) dense[i] = dense[i - 1];  // ties across indices
    for (std::size_t n : {656u, 6554u}) EXPECT_EQ(keepLargest(dense, n).indices, referenceLargest(dense, n)) << n;
}

TEST(KeepLargestReference, NamesTheFirstNonFiniteCoefficient) {
    std::vector<float> dense = randomVector(Kind::Ties, 300, 5);
    dense[123] = std::numeric_limits<float>::quiet_NaN();
    dense[200] = std::numeric_limits<float>::infinity();
    test::expectErrorContaining([&] { keepLargest(dense, 10); }, "coefficient 123 is not finite");
    dense[123] = 1.0f;
    test::expectErrorContaining([&] { keepLargest(dense, 10); }, "coefficient 200 is not finite");
    dense[200] = -std::numeric_limits<float>::quiet_NaN();
    test::expectErrorContaining([&] { keepLargest(dense, 1000); }, "coefficient 200 is not finite");
}

}  // namespace
}  // namespace opal
