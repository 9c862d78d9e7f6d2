// The Haar transform against the textbook nonstandard decomposition written as separate
// passes (Stollnitz, DeRose and Salesin 1995, section 3): per level, one Haar step along
// every row of the active block, then one along every column. The library fuses each
// level into one pass over 2 x 2 blocks; the arithmetic per value is the same, so the
// results must be the same bits (the bake is byte-identical across runs and versions).
#include "schema/wavelet/haar.h"

#include "tests/wavelet/wavelet_test_util.h"

#include <gtest/gtest.h>

#include <cstring>
#include <numbers>

namespace opal {
namespace {

// One step on `count` values `stride` apart (channel-interleaved cells).
template <typename T>
void stepForward(T* v, std::size_t count, std::size_t stride) {
    const T k = T(1) / std::numbers::sqrt2_v<T>;
    std::vector<T> out(count);
    for (std::size_t j = 0; j < count / 2; ++j) {
        const T a = v[2 * j * stride], b = v[(2 * j + 1) * stride];
        out[j] = (a + b) * k;
        out[count / 2 + j] = (a - b) * k;
    }
    for (std::size_t j = 0; j < count; ++j) v[j * stride] = out[j];
}

template <typename T>
void stepInverse(T* v, std::size_t count, std::size_t stride) {
    const T k = T(1) / std::numbers::sqrt2_v<T>;
    std::vector<T> out(count);
    for (std::size_t j = 0; j < count / 2; ++j) {
        const T lo = v[j * stride], hi = v[(count / 2 + j) * stride];
        out[2 * j] = (lo + hi) * k;
        out[2 * j + 1] = (lo - hi) * k;
    }
    for (std::size_t j = 0; j < count; ++j) v[j * stride] = out[j];
}

template <typename T>
void referenceForward(std::vector<T>& grid, std::size_t size, std::size_t channels) {
    for (std::size_t s = size; s > 1; s /= 2)
        for (std::size_t ch = 0; ch < channels; ++ch) {
            for (std::size_t r = 0; r < s; ++r) stepForward(grid.data() + r * size * channels + ch, s, channels);
            for (std::size_t c = 0; c < s; ++c) stepForward(grid.data() + c * channels + ch, s, size * channels);
        }
}

template <typename T>
void referenceInverse(std::vector<T>& grid, std::size_t size, std::size_t channels) {
    for (std::size_t s = 2; s <= size; s *= 2)
        for (std::size_t ch = 0; ch < channels; ++ch) {
            for (std::size_t c = 0; c < s; ++c) stepInverse(grid.data() + c * channels + ch, s, size * channels);
            for (std::size_t r = 0; r < s; ++r) stepInverse(grid.data() + r * size * channels + ch, s, channels);
        }
}

template <typename T>
void expectSameBits(const std::vector<T>& a, const std::vector<T>& b, const char* what) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i)
        ASSERT_EQ(std::memcmp(&a[i], &b[i], sizeof(T)), 0) << what << " value " << i << ": " << a[i] << " vs " << b[i];
}

template <typename T>
class HaarPassesTest : public ::testing::Test {};
using Precisions = ::testing::Types<float, double>;
TYPED_TEST_SUITE(HaarPassesTest, Precisions);

TYPED_TEST(HaarPassesTest, ForwardAndInverseMatchSeparatePassesBitForBit) {
    using T = TypeParam;
    for (std::uint32_t channels : {1u, 2u, 3u})
        for (std::uint32_t size : {1u, 2u, 4u, 16u, 64u}) {
            const std::vector<T> original = test::randomValues<T>(size * size * channels, 31 * size + channels);
            std::vector<T> fast = original, reference = original;
            haarForward2D<T>(fast, size, channels);
            referenceForward(reference, size, channels);
            expectSameBits(fast, reference, "forward");
            haarInverse2D<T>(fast, size, channels);
            referenceInverse(reference, size, channels);
            expectSameBits(fast, reference, "inverse");
        }
}

TEST(HaarPasses, ChartsMatchSeparatePassesBitForBit) {
    const ChartLayout layout{16, 6};  // a 65,536-sample bake's row
    const std::vector<float> original = test::randomValues<float>(layout.cells(), 8);
    std::vector<float> fast = original;
    haarForwardCharts<float>(fast, layout);
    for (std::uint32_t chart = 0; chart < layout.charts; ++chart) {
        const auto first = original.begin() + chart * layout.cellsPerChart();
        std::vector<float> reference(first, first + layout.cellsPerChart());
        referenceForward(reference, layout.size(), 1);
        const auto got = fast.begin() + chart * layout.cellsPerChart();
        expectSameBits(std::vector<float>(got, got + layout.cellsPerChart()), reference, "chart");
    }
}

}  // namespace
}  // namespace opal
