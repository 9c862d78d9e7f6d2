#include "schema/wavelet/haar.h"

#include "tests/wavelet/wavelet_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace opal {
namespace {

template <typename T>
class HaarTest : public ::testing::Test {};
using Precisions = ::testing::Types<float, double>;
TYPED_TEST_SUITE(HaarTest, Precisions);


TYPED_TEST(HaarTest, ReconstructsRandomGrids) {
    using T = TypeParam;
    for (std::uint32_t channels : {1u, 3u})
        for (std::uint32_t size : {1u, 2u, 4u, 8u, 64u}) {
            const std::vector<T> original = test::randomValues<T>(size * size * channels, size);
            std::vector<T> grid = original;
            haarForward2D<T>(grid, size, channels);
            EXPECT_GT(test::relativeError<T>(grid, original), size > 1 ? 1e-3 : -1.0);
            haarInverse2D<T>(grid, size, channels);
            EXPECT_LT(test::relativeError<T>(grid, original), test::tolerance(T()))
                << "size " << size << " channels " << channels;
        }
}

TYPED_TEST(HaarTest, PreservesEnergy) {
    using T = TypeParam;
    std::vector<T> grid = test::randomValues<T>(64 * 64, 7);
    const double before = test::energy<T>(grid);
    haarForward2D<T>(grid, 64);
    EXPECT_NEAR(test::energy<T>(grid), before, before * test::tolerance(T()));
}

// One 1D Haar function of the level whose coefficients sit in [s/2, s), on [0, size):
// the scaling function (box) or the wavelet (+ then -), both of unit norm, index k.
std::vector<double> haar1D(std::uint32_t size, std::uint32_t s, std::uint32_t k, bool wavelet) {
    const std::uint32_t width = 2 * size / s;
    std::vector<double> f(size, 0.0);
    for (std::uint32_t x = 0; x < width; ++x)
        f[k * width + x] = (wavelet && x >= width / 2 ? -1.0 : 1.0) / std::sqrt(double(width));
    return f;
}

// The nonstandard Haar basis function of coefficient (r, c), written from its definition
// (Stollnitz, DeRose and Salesin 1995, section 3): at the level s of (r, c), a product
// of a scaling function or wavelet along x and along y; (0, 0) is the constant.
std::vector<double> nonstandardBasis(std::uint32_t size, std::uint32_t r, std::uint32_t c) {
    std::uint32_t s = 2;
    while (std::max(r, c) >= s) s *= 2;
    const bool xWavelet = c >= s / 2, yWavelet = r >= s / 2;
    std::vector<double> fx = haar1D(size, s, xWavelet ? c - s / 2 : c, xWavelet);
    std::vector<double> fy = haar1D(size, s, yWavelet ? r - s / 2 : r, yWavelet);
    if (r == 0 && c == 0) fx = fy = std::vector<double>(size, 1.0 / std::sqrt(double(size)));
    std::vector<double> basis(size * size);
    for (std::uint32_t y = 0; y < size; ++y)
        for (std::uint32_t x = 0; x < size; ++x) basis[y * size + x] = fy[y] * fx[x];
    return basis;
}

TEST(Haar, MatchesExplicitNonstandardBasis) {
    for (std::uint32_t size : {2u, 4u, 8u}) {
        const std::vector<double> signal = test::randomValues<double>(size * size, 11);
        std::vector<double> coefficients = signal;
        haarForward2D<double>(coefficients, size);
        for (std::uint32_t r = 0; r < size; ++r)
            for (std::uint32_t c = 0; c < size; ++c) {
                const std::vector<double> basis = nonstandardBasis(size, r, c);
                double projection = 0;
                for (std::size_t i = 0; i < basis.size(); ++i) projection += basis[i] * signal[i];
                EXPECT_NEAR(coefficients[r * size + c], projection, 1e-12)
                    << "size " << size << " coefficient (" << r << ", " << c << ")";
            }
    }
}

TEST(Haar, ImpulseResponsesAreOrthonormal) {
    const std::uint32_t size = 8, n = size * size;
    std::vector<std::vector<double>> columns(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        columns[i].assign(n, 0.0);
        columns[i][i] = 1.0;
        haarForward2D<double>(columns[i], size);
    }
    for (std::uint32_t i = 0; i < n; ++i)
        for (std::uint32_t j = 0; j < n; ++j) {
            double dot = 0;
            for (std::uint32_t k = 0; k < n; ++k) dot += columns[i][k] * columns[j][k];
            EXPECT_NEAR(dot, i == j ? 1.0 : 0.0, 1e-12) << i << ", " << j;
        }
}

TEST(Haar, ConstantGridHasOnlyTheAverage) {
    std::vector<float> grid(16 * 16, 2.0f);
    haarForward2D<float>(grid, 16);
    EXPECT_NEAR(grid[0], 2.0f * 16, 1e-5);  // sum / size for the orthonormal constant
    for (std::size_t i = 1; i < grid.size(); ++i) EXPECT_NEAR(grid[i], 0.0f, 1e-5) << i;
}

TEST(Haar, ChannelsAreIndependent) {
    const std::uint32_t size = 16, channels = 3;
    std::vector<float> interleaved = test::randomValues<float>(size * size * channels, 5);
    std::vector<std::vector<float>> planes(channels, std::vector<float>(size * size));
    for (std::uint32_t i = 0; i < size * size; ++i)
        for (std::uint32_t ch = 0; ch < channels; ++ch)
            planes[ch][i] = interleaved[i * channels + ch];
    haarForward2D<float>(interleaved, size, channels);
    for (std::uint32_t ch = 0; ch < channels; ++ch) {
        haarForward2D<float>(planes[ch], size);
        for (std::uint32_t i = 0; i < size * size; ++i)
            ASSERT_EQ(interleaved[i * channels + ch], planes[ch][i])
                << "channel " << ch << " cell " << i;
    }
}

TEST(Haar, ChartsTransformEachChart) {
    // 16 charts of 64 x 64 x 1 is large enough for the parallel path, 3 of 8 x 8 is not.
    for (ChartLayout layout : {ChartLayout{3, 3}, ChartLayout{16, 6}}) {
        const std::vector<float> original = test::randomValues<float>(layout.cells(), 3);
        std::vector<float> data = original, expected = original;
        haarForwardCharts<float>(data, layout);
        for (std::uint32_t c = 0; c < layout.charts; ++c)
            haarForward2D<float>(
                std::span(expected).subspan(c * layout.cellsPerChart(), layout.cellsPerChart()),
                layout.size());
        EXPECT_EQ(data, expected);
        haarInverseCharts<float>(data, layout);
        EXPECT_LT(test::relativeError<float>(data, original), 1e-6);
    }
}

TEST(Haar, SupportCellsCountWhatEachBasisFunctionCovers) {
    // The independent truth: synthesize each unit coefficient and count its nonzero cells.
    for (std::uint32_t size : {1u, 2u, 8u, 16u}) {
        const std::vector<float> cells = haarSupportCells(size);
        ASSERT_EQ(cells.size(), std::size_t(size) * size);
        for (std::size_t i = 0; i < cells.size(); ++i) {
            std::vector<double> grid(cells.size(), 0.0);
            grid[i] = 1.0;
            haarInverse2D<double>(grid, size);
            const auto covered = std::count_if(grid.begin(), grid.end(), [](double v) { return v != 0.0; });
            EXPECT_EQ(double(covered), double(cells[i])) << "size " << size << " coefficient " << i;
        }
    }
    EXPECT_THROW(haarSupportCells(12), Error);
}

TEST(Haar, RejectsBadInput) {
    std::vector<float> grid(36);
    EXPECT_THROW(haarForward2D<float>(grid, 6), Error);
    EXPECT_THROW(haarForward2D<float>(std::span<float>(grid).first(0), 0), Error);
    EXPECT_THROW(haarInverse2D<float>(grid, 4), Error);  // 36 values for a 4 x 4 grid
    EXPECT_THROW(haarForward2D<float>(std::span<float>(grid).first(16), 4, 0), Error);
    EXPECT_THROW(haarForwardCharts<float>(grid, ChartLayout{2, 2}), Error);  // needs 32
    test::expectErrorContaining([&] { haarForward2D<float>(grid, 6); },
                                "haarForward2D: grid size 6 is not a power of two");
    test::expectErrorContaining([&] { haarInverse2D<float>(grid, 4); },
                                "grid has 36 values, expected 4 x 4 x 1 channels = 16");
}

}  // namespace
}  // namespace opal
