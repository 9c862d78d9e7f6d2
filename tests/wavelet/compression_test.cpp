// The two wavelet compression rules on signals like the transfer: smooth bumps on a
// chart (docs/ARCHITECTURE.md#compression). Energies are measured in the signal domain.
#include "schema/wavelet/cdf97.h"
#include "schema/wavelet/haar.h"
#include "schema/wavelet/sparse.h"

#include "tests/wavelet/wavelet_test_util.h"

#include <gtest/gtest.h>

#include <cmath>

namespace opal {
namespace {

constexpr std::uint32_t kSize = 64;

std::vector<float> gaussianBump(double cx, double cy, double sigma) {
    std::vector<float> grid(kSize * kSize);
    for (std::uint32_t y = 0; y < kSize; ++y)
        for (std::uint32_t x = 0; x < kSize; ++x)
            grid[y * kSize + x] =
                float(std::exp(-((x - cx) * (x - cx) + (y - cy) * (y - cy)) / (2 * sigma * sigma)));
    return grid;
}

std::vector<float> densify(const SparseVector& kept, std::size_t size) {
    std::vector<float> dense(size, 0.0f);
    for (std::size_t k = 0; k < kept.size(); ++k) dense[kept.indices[k]] = kept.values[k];
    return dense;
}

double predictedEnergy(const SparseVector& kept, const std::vector<float>& norms) {
    double sum = 0;
    for (std::size_t k = 0; k < kept.size(); ++k)
        sum += double(kept.values[k]) * kept.values[k] * norms[kept.indices[k]];
    return sum;
}

// Inverse 9/7 transform of the kept coefficients.
std::vector<float> reconstructCdf97(const SparseVector& kept) {
    std::vector<float> grid = densify(kept, kSize * kSize);
    cdf97Inverse2D<float>(grid, kSize);
    return grid;
}

TEST(Compression, SmoothBumpKeepsItsEnergyWithFewCdf97Coefficients) {
    const std::vector<float> signal = gaussianBump(27.3, 35.1, 6.0);
    std::vector<float> coefficients = signal;
    cdf97Forward2D<float>(coefficients, kSize);
    const std::vector<float> norms = cdf97SynthesisNormsSquared(kSize);

    const SparseVector kept = keepEnergyFraction(coefficients, 0.999, norms);
    const std::vector<float> approx = reconstructCdf97(kept);
    EXPECT_LE(kept.size(), kSize * kSize / 10);
    const double signalEnergy = test::energy<float>(signal);
    EXPECT_GE(test::energy<float>(approx), 0.99 * signalEnergy);
    // Stronger: the error itself carries at most 1% of the energy.
    EXPECT_LT(std::pow(test::relativeError<float>(approx, signal), 2), 0.01);
}

TEST(Compression, NormsPredictTheReconstructedEnergy) {
    // Random coefficients (all frequencies and the boundary functions) under several
    // thresholds: the cross terms of the biorthogonal basis average out, so sum c_i^2 g_i
    // must match the energy of the reconstruction closely, and clearly better than the
    // orthonormal guess g_i = 1.
    const std::vector<float> norms = cdf97SynthesisNormsSquared(kSize);
    const std::vector<float> ones(kSize * kSize, 1.0f);
    const std::vector<float> coefficients = test::randomValues<float>(kSize * kSize, 31);
    for (double fraction : {0.5, 0.9, 1.0}) {
        const SparseVector kept = keepEnergyFraction(coefficients, fraction, norms);
        const double actual = test::energy<float>(reconstructCdf97(kept));
        const double withNorms = std::abs(predictedEnergy(kept, norms) - actual);
        EXPECT_LT(withNorms, 0.02 * actual) << fraction;
        EXPECT_LT(2 * withNorms, std::abs(predictedEnergy(kept, ones) - actual)) << fraction;
    }
}

TEST(Compression, NormsPredictASmoothBumpsEnergy) {
    // A coarse-scale signal lives on the coarse functions, whose overlaps do not cancel:
    // the prediction is still within a few percent (the 8 x 8 coarsest band of cdf97.h).
    const std::vector<float> signal = gaussianBump(31.5, 31.5, 12.0);
    std::vector<float> coefficients = signal;
    cdf97Forward2D<float>(coefficients, kSize);
    const std::vector<float> norms = cdf97SynthesisNormsSquared(kSize);
    for (double fraction : {0.9, 0.99, 1.0}) {
        const SparseVector kept = keepEnergyFraction(coefficients, fraction, norms);
        const double actual = test::energy<float>(reconstructCdf97(kept));
        EXPECT_NEAR(predictedEnergy(kept, norms), actual, 0.08 * actual) << fraction;
    }
}

TEST(Compression, Cdf97NeedsFewerCoefficientsThanHaarOnASmoothBump) {
    // The paper's reason for 9/7 in step 2: for the same error, a smooth signal needs
    // fewer 9/7 than Haar coefficients.
    const std::vector<float> signal = gaussianBump(20.2, 41.7, 5.0);
    std::vector<float> haar = signal, cdf = signal;
    haarForward2D<float>(haar, kSize);
    cdf97Forward2D<float>(cdf, kSize);
    const SparseVector haarKept = keepEnergyFraction(haar, 0.9999);
    const SparseVector cdfKept = keepEnergyFraction(cdf, 0.9999, cdf97SynthesisNormsSquared(kSize));

    std::vector<float> haarApprox = densify(haarKept, kSize * kSize);
    haarInverse2D<float>(haarApprox, kSize);
    const double haarError = test::relativeError<float>(haarApprox, signal);
    const double cdfError = test::relativeError<float>(reconstructCdf97(cdfKept), signal);
    EXPECT_LT(cdfKept.size(), haarKept.size() / 2);
    EXPECT_LT(cdfError, 2 * haarError);  // and not at the price of a larger error
}

TEST(Compression, HaarKeepLargestIsTheBestNTermApproximation) {
    // Orthonormal basis: dropping coefficients loses exactly their energy.
    const std::vector<float> signal = gaussianBump(10.0, 50.0, 3.0);
    std::vector<float> coefficients = signal;
    haarForward2D<float>(coefficients, kSize);
    const SparseVector kept = keepLargest(coefficients, 41);  // ~1%, as in step 1
    std::vector<float> approx = densify(kept, kSize * kSize);
    haarInverse2D<float>(approx, kSize);
    double keptEnergy = 0;
    for (float v : kept.values) keptEnergy += double(v) * v;
    EXPECT_NEAR(test::energy<float>(approx), keptEnergy, 1e-5 * keptEnergy);
    const double errorEnergy =
        std::pow(test::relativeError<float>(approx, signal), 2) * test::energy<float>(signal);
    EXPECT_NEAR(errorEnergy, test::energy<float>(signal) - keptEnergy, 1e-4 * keptEnergy);
}

}  // namespace
}  // namespace opal
