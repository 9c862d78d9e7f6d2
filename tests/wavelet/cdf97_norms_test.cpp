#include "schema/wavelet/cdf97.h"

#include "tests/wavelet/wavelet_test_util.h"

#include <gtest/gtest.h>

namespace opal {
namespace {

// Brute force: the squared norm of the inverse transform of each unit impulse.
std::vector<double> normsByImpulses(std::uint32_t size) {
    std::vector<double> norms(size * size);
    for (std::uint32_t i = 0; i < size * size; ++i) {
        std::vector<double> grid(size * size, 0.0);
        grid[i] = 1.0;
        cdf97Inverse2D<double>(grid, size);
        norms[i] = test::energy<double>(grid);
    }
    return norms;
}

TEST(Cdf97Norms, MatchBruteForceImpulses) {
    for (std::uint32_t size : {1u, 2u, 4u, 16u, 32u}) {
        const std::vector<float> norms = cdf97SynthesisNormsSquared(size);
        const std::vector<double> expected = normsByImpulses(size);
        ASSERT_EQ(norms.size(), expected.size());
        for (std::size_t i = 0; i < norms.size(); ++i)
            EXPECT_NEAR(norms[i], expected[i], 1e-6 * expected[i])
                << "size " << size << " index " << i;
    }
}

TEST(Cdf97Norms, FinestInteriorNormsAreTheFilterNorms) {
    // Away from the boundary, a finest-level function is one synthesis filter per axis:
    // the synthesis low-pass is the modulated 7-tap analysis high-pass and the synthesis
    // high-pass the modulated 9-tap analysis low-pass, so their squared norms are the sums
    // of the squared analysis taps (values tabulated in cdf97_test.cpp).
    const double low =
        0.788485616405665 * 0.788485616405665 +
        2 * (0.418092273222212 * 0.418092273222212 + 0.040689417609558 * 0.040689417609558 +
             0.064538882628938 * 0.064538882628938);
    const double high =
        0.852698679009403 * 0.852698679009403 +
        2 * (0.377402855612654 * 0.377402855612654 + 0.110624404418423 * 0.110624404418423 +
             0.023849465019380 * 0.023849465019380 + 0.037828455506995 * 0.037828455506995);
    const std::uint32_t size = 64;
    const std::vector<float> norms = cdf97SynthesisNormsSquared(size);
    EXPECT_NEAR(norms[48 * size + 48], high * high, 1e-6);  // high x high
    EXPECT_NEAR(norms[48 * size + 16], high * low, 1e-6);   // high (y) x low (x)
    EXPECT_NEAR(norms[16 * size + 40], low * high, 1e-6);
}

TEST(Cdf97Norms, LayoutTilesTheChartNorms) {
    const ChartLayout layout{3, 3};
    const std::vector<float> chart = cdf97SynthesisNormsSquared(layout.size());
    const std::vector<float> all = cdf97SynthesisNormsSquared(layout);
    ASSERT_EQ(all.size(), layout.cells());
    for (std::size_t i = 0; i < all.size(); ++i) EXPECT_EQ(all[i], chart[i % chart.size()]) << i;
}

TEST(Cdf97Norms, RejectBadSizes) {
    test::expectErrorContaining([] { cdf97SynthesisNormsSquared(12); },
                                "grid size 12 is not a power of two");
    EXPECT_THROW(cdf97SynthesisNormsSquared(0), Error);
    EXPECT_THROW(cdf97SynthesisNormsSquared(ChartLayout{1, 20}), Error);
}

}  // namespace
}  // namespace opal
