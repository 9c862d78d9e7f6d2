#include "schema/wavelet/cdf97.h"

#include "tests/wavelet/wavelet_test_util.h"

#include <gtest/gtest.h>

#include <array>

namespace opal {
namespace {

template <typename T>
class Cdf97Test : public ::testing::Test {};
using Precisions = ::testing::Types<float, double>;
TYPED_TEST_SUITE(Cdf97Test, Precisions);


// The sqrt(2)-normalized CDF 9/7 analysis filters as tabulated in the literature
// (Daubechies, "Ten lectures on wavelets", table 8.3; the JPEG 2000 irreversible pair up
// to band scaling): low-pass centered on an even sample, high-pass on an odd one.
constexpr std::array<double, 5> kLowTaps = {0.852698679009403, 0.377402855612654,
                                            -0.110624404418423, -0.023849465019380,
                                            0.037828455506995};
constexpr std::array<double, 4> kHighTaps = {0.788485616405665, -0.418092273222212,
                                             -0.040689417609558, 0.064538882628938};

// x[i] for any integer i under whole-sample symmetric extension (x[-k] = x[k],
// x[n-1+k] = x[n-1-k]).
double mirrored(const std::vector<double>& x, long i) {
    const long n = long(x.size()), period = 2 * (n - 1);
    i = ((i % period) + period) % period;
    return x[i < n ? i : period - i];
}

// Symmetric-filter convolution at `center`, reading the symmetric extension of x.
template <std::size_t N>
double convolve(const std::array<double, N>& taps, const std::vector<double>& x, long center) {
    double sum = taps[0] * mirrored(x, center);
    for (long k = 1; k < long(N); ++k)
        sum += taps[k] * (mirrored(x, center - k) + mirrored(x, center + k));
    return sum;
}

TYPED_TEST(Cdf97Test, ReconstructsRandomGrids) {
    using T = TypeParam;
    for (std::uint32_t channels : {1u, 3u})
        for (std::uint32_t size : {1u, 2u, 4u, 8u, 64u}) {
            const std::vector<T> original =
                test::randomValues<T>(size * size * channels, 100 + size);
            std::vector<T> grid = original;
            cdf97Forward2D<T>(grid, size, channels);
            EXPECT_GT(test::relativeError<T>(grid, original), size > 1 ? 1e-3 : -1.0);
            cdf97Inverse2D<T>(grid, size, channels);
            EXPECT_LT(test::relativeError<T>(grid, original), test::tolerance(T()))
                << "size " << size << " channels " << channels;
        }
}

TEST(Cdf97, AnalysisStepMatchesDirectConvolutionInTheInterior) {
    const std::size_t n = 64;
    const std::vector<double> x = test::randomValues<double>(n, 21);
    std::vector<double> y = x;
    cdf97AnalysisStep1D<double>(y);
    for (long l = 2; l < long(n / 2) - 2; ++l) {  // filters fully inside the signal
        EXPECT_NEAR(y[l], convolve(kLowTaps, x, 2 * l), 1e-11) << "low " << l;
        EXPECT_NEAR(y[n / 2 + l], convolve(kHighTaps, x, 2 * l + 1), 1e-11) << "high " << l;
    }
}

TEST(Cdf97, AnalysisStepExtendsSymmetricallyAtTheBoundaries) {
    for (std::size_t n : {2u, 4u, 6u, 8u, 16u}) {
        const std::vector<double> x = test::randomValues<double>(n, 22 + n);
        std::vector<double> y = x;
        cdf97AnalysisStep1D<double>(y);
        for (long l = 0; l < long(n / 2); ++l) {
            EXPECT_NEAR(y[l], convolve(kLowTaps, x, 2 * l), 1e-11) << "n " << n << " low " << l;
            EXPECT_NEAR(y[n / 2 + l], convolve(kHighTaps, x, 2 * l + 1), 1e-11)
                << "n " << n << " high " << l;
        }
    }
}

TEST(Cdf97, SynthesisStepInvertsAnalysisStep) {
    for (std::size_t n : {2u, 6u, 64u}) {
        const std::vector<double> x = test::randomValues<double>(n, 23);
        std::vector<double> y = x;
        cdf97AnalysisStep1D<double>(y);
        cdf97SynthesisStep1D<double>(y);
        EXPECT_LT(test::relativeError<double>(y, x), 1e-14) << n;
    }
}

TEST(Cdf97, ConstantGridHasOnlyTheCoarsestBand) {
    // Symmetric extension keeps a constant constant and the high-pass filter annihilates
    // constants, so every detail vanishes, boundaries included; each level multiplies the
    // low-low band by the low-pass DC gain sqrt(2) twice. 64 x 64 has 3 levels, leaving 8 x 8.
    const std::uint32_t size = 64;
    ASSERT_EQ(cdf97CoarsestSize(size), 8u);
    std::vector<double> grid(size * size, 3.0);
    cdf97Forward2D<double>(grid, size);
    for (std::uint32_t r = 0; r < size; ++r)
        for (std::uint32_t c = 0; c < size; ++c)
            EXPECT_NEAR(grid[r * size + c], r < 8 && c < 8 ? 3.0 * 8 : 0.0, 1e-11)
                << r << ", " << c;
}

TEST(Cdf97, CoarsestSizeIsEightOrOneLevel) {
    EXPECT_EQ(cdf97CoarsestSize(1), 1u);
    EXPECT_EQ(cdf97CoarsestSize(2), 1u);
    EXPECT_EQ(cdf97CoarsestSize(8), 4u);
    EXPECT_EQ(cdf97CoarsestSize(16), 8u);
    EXPECT_EQ(cdf97CoarsestSize(128), 8u);
}

// The nonstandard decomposition written out with 1D steps and plain strided copies:
// per level, every row of the active block, then every column, until the 8 x 8 band.
std::vector<double> forward2DByOneDimensionalSteps(std::vector<double> grid, std::uint32_t size) {
    for (std::uint32_t s = size; s >= 2 && (s == size || s > 8); s /= 2) {
        std::vector<double> line(s);
        for (std::uint32_t r = 0; r < s; ++r) {
            for (std::uint32_t c = 0; c < s; ++c) line[c] = grid[r * size + c];
            cdf97AnalysisStep1D<double>(line);
            for (std::uint32_t c = 0; c < s; ++c) grid[r * size + c] = line[c];
        }
        for (std::uint32_t c = 0; c < s; ++c) {
            for (std::uint32_t r = 0; r < s; ++r) line[r] = grid[r * size + c];
            cdf97AnalysisStep1D<double>(line);
            for (std::uint32_t r = 0; r < s; ++r) grid[r * size + c] = line[r];
        }
    }
    return grid;
}

TEST(Cdf97, Forward2DIsTheNonstandardDecomposition) {
    for (std::uint32_t size : {2u, 8u, 16u, 32u, 128u}) {
        const std::vector<double> signal = test::randomValues<double>(size * size, 24);
        std::vector<double> grid = signal;
        cdf97Forward2D<double>(grid, size);
        EXPECT_LT(test::relativeError<double>(grid, forward2DByOneDimensionalSteps(signal, size)),
                  1e-14)
            << size;
    }
}

TEST(Cdf97, ChannelsAreIndependent) {
    const std::uint32_t size = 16, channels = 3;
    std::vector<float> interleaved = test::randomValues<float>(size * size * channels, 25);
    std::vector<std::vector<float>> planes(channels, std::vector<float>(size * size));
    for (std::uint32_t i = 0; i < size * size; ++i)
        for (std::uint32_t ch = 0; ch < channels; ++ch)
            planes[ch][i] = interleaved[i * channels + ch];
    cdf97Inverse2D<float>(interleaved, size, channels);
    for (std::uint32_t ch = 0; ch < channels; ++ch) {
        cdf97Inverse2D<float>(planes[ch], size);
        for (std::uint32_t i = 0; i < size * size; ++i)
            ASSERT_NEAR(interleaved[i * channels + ch], planes[ch][i], 1e-6)
                << "channel " << ch << " cell " << i;
    }
}

TEST(Cdf97, ChartsTransformEachChart) {
    // 16 charts of 64 x 64 x 3 takes the parallel path, 3 charts of 4 x 4 the serial one.
    for (std::uint32_t channels : {1u, 3u})
        for (ChartLayout layout : {ChartLayout{3, 2}, ChartLayout{16, 6}}) {
            const std::size_t perChart = layout.cellsPerChart() * channels;
            const std::vector<float> original =
                test::randomValues<float>(layout.cells() * channels, 26);
            std::vector<float> data = original, expected = original;
            cdf97ForwardCharts<float>(data, layout, channels);
            for (std::uint32_t c = 0; c < layout.charts; ++c)
                cdf97Forward2D<float>(std::span(expected).subspan(c * perChart, perChart),
                                      layout.size(), channels);
            EXPECT_EQ(data, expected);
            cdf97InverseCharts<float>(data, layout, channels);
            EXPECT_LT(test::relativeError<float>(data, original), 1e-6);
        }
}

TEST(Cdf97, RejectsBadInput) {
    std::vector<float> grid(24);
    test::expectErrorContaining([&] { cdf97Forward2D<float>(grid, 3); },
                                "cdf97Forward2D: grid size 3 is not a power of two");
    test::expectErrorContaining(
        [&] { cdf97Inverse2D<float>(grid, 4); },
        "cdf97Inverse2D: grid has 24 values, expected 4 x 4 x 1 channels = 16");
    test::expectErrorContaining(
        [&] {
            cdf97InverseCharts<float>(grid, ChartLayout{2, 1}, 2);
        },
        "cdf97InverseCharts: data has 24 values, expected 2 charts x 2 x 2 x 2");
    test::expectErrorContaining([&] { cdf97AnalysisStep1D<float>(std::span(grid).first(5)); },
                                "signal length 5 is not an even number");
    EXPECT_THROW(cdf97SynthesisStep1D<float>(std::span(grid).first(0)), Error);
}

}  // namespace
}  // namespace opal
