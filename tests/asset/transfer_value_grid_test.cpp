// The transfer's value grid (transfer_value_grid.h): rounding moves a value by at most half
// a step in the weighted amplitude u = c sqrt(g_p) sqrt(a_j), is idempotent, and leaves
// step-0 matrices untouched; the weights are the 9/7 synthesis norms and Haar supports.
#include "schema/asset/transfer_value_grid.h"

#include "schema/wavelet/cdf97.h"
#include "schema/wavelet/haar.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <random>

namespace opal {
namespace {

// A random 2-chart 16 x 16 matrix with values spread over 12 octaves.
SparseMatrix randomMatrix(const ChartLayout& layout, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> octave(-12.0f, 0.0f), sign(-1.0f, 1.0f), coin(0.0f, 1.0f);
    SparseMatrix m;
    m.rows = m.cols = std::uint32_t(layout.cells());
    m.rowOffsets.push_back(0);
    for (std::uint32_t p = 0; p < m.rows; ++p) {
        for (std::uint32_t j = 0; j < m.cols; ++j)
            if (coin(rng) < 0.05f) {
                m.columns.push_back(j);
                m.values.push_back(std::copysign(std::exp2(octave(rng)), sign(rng)));
            }
        m.rowOffsets.push_back(m.columns.size());
    }
    return m;
}

TEST(TransferValueGrid, WeightsAreSynthesisNormsTimesHaarSupports) {
    const ChartLayout layout{2, 4};
    const TransferValueGrid grid(layout);
    const std::vector<float> g = cdf97SynthesisNormsSquared(16), a = haarSupportCells(16);
    for (std::uint32_t p : {0u, 5u, 255u, 256u, 300u})
        for (std::uint32_t j : {0u, 17u, 256u, 511u})
            EXPECT_DOUBLE_EQ(grid.weight(p, j), std::sqrt(double(g[p % 256])) * std::sqrt(double(a[j % 256])));
}

TEST(TransferValueGrid, RoundingMovesAWeightedValueByAtMostHalfAStepAndIsIdempotent) {
    const ChartLayout layout{2, 4};
    const TransferValueGrid grid(layout);
    const double step = 3e-3;
    const SparseMatrix original = randomMatrix(layout, 4);
    SparseMatrix rounded = original;
    grid.round(rounded, step);
    std::size_t changed = 0;
    for (std::uint32_t p = 0; p < original.rows; ++p)
        for (std::uint64_t e = original.rowOffsets[p]; e < original.rowOffsets[p + 1]; ++e) {
            const double w = grid.weight(p, original.columns[e]);
            const double moved = std::abs(double(rounded.values[e]) - double(original.values[e])) * w;
            EXPECT_LE(moved, 0.5 * step * (1.0 + 1e-6) + 1e-7 * std::abs(original.values[e]) * w);
            changed += rounded.values[e] != original.values[e];
        }
    EXPECT_GT(changed, original.values.size() / 2);
    SparseMatrix again = rounded;
    grid.round(again, step);
    for (std::size_t e = 0; e < again.values.size(); ++e)
        ASSERT_EQ(std::bit_cast<std::uint32_t>(again.values[e]), std::bit_cast<std::uint32_t>(rounded.values[e]));
    SparseMatrix exact = original;
    grid.round(exact, 0.0);
    EXPECT_EQ(exact.values, original.values);
}

}  // namespace
}  // namespace opal
