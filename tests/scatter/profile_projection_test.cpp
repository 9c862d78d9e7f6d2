// The coefficients fitted beyond the self disk (schema/scatter/profile_projection.h,
// docs/ARCHITECTURE.md#pca): the plain projection at rho = 0, the normal equations of the
// ridge least-squares fit at rho > 0 checked by brute force, and a profile that ends inside
// the disk leaves nothing for the transfer to carry.
#include "schema/error.h"
#include "schema/scatter/dipole.h"
#include "schema/scatter/material_sampler.h"
#include "schema/scatter/profile_projection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace opal {
namespace {

// A bake-like basis: K = 16 over a 60 mm object (rMax its size), the default range.
const ProfileBasis& bakeLikeBasis() {
    static const ProfileBasis basis = [] {
        ProfileBasisSettings settings;
        settings.K = 16;
        settings.rMax = 60.0;
        return ProfileBasis::fit(settings);
    }();
    return basis;
}

TEST(ProfileProjection, AtRadiusZeroIsThePlainProjectionBitForBit) {
    const ProfileBasis& basis = bakeLikeBasis();
    const ProfileProjection plain(basis, 0.0);
    for (const DipoleCoefficients& c : sampleChannels(basis.range(), 20, 31))
        EXPECT_EQ(plain.coefficients(c), basis.coefficients(c));
}

// sum_{l: r_l >= rho} w_l b_k (sum_j s_j b_j - R_d) + mu (lambda_1 / lambda_k) s_k = 0 for
// every k: the gradient of the fit's objective, in plain loops; then the nonnegative step.
TEST(ProfileProjection, SolvesTheRidgeLeastSquaresBeyondTheDisk) {
    const ProfileBasis& basis = bakeLikeBasis();
    const double rho = 0.9;
    const ProfileProjection fit(basis, rho);
    const std::span<const double> r = basis.radii(), w = basis.weights(), lambda = basis.eigenvalues();
    const std::size_t K = std::size_t(basis.K()), L = r.size();
    for (const DipoleCoefficients& c : sampleChannels(basis.range(), 40, 77)) {
        const std::vector<double> s = fit.unconstrainedCoefficients(c);
        EXPECT_EQ(fit.coefficients(c), basis.nonnegative(s));
        double scale = 0.0;
        std::vector<double> gradient(K, 0.0);
        for (std::size_t l = 0; l < L; ++l) {
            if (r[l] < rho) continue;
            const double residual = basis.reconstruct(s, r[l]) - dipoleProfile(r[l], c);
            for (std::size_t k = 0; k < K; ++k) {
                const double b = basis.values()[k * L + l];
                gradient[k] += w[l] * b * residual;
                scale = std::max({scale, std::abs(w[l] * b * dipoleProfile(r[l], c)),
                                  std::abs(w[l] * b * basis.reconstruct(s, r[l]))});
            }
        }
        for (std::size_t k = 0; k < K; ++k) {
            const double ridge = ProfileProjection::kRidge * lambda[0] / lambda[k] * s[k];
            gradient[k] += ridge;
            scale = std::max(scale, std::abs(ridge));
        }
        for (std::size_t k = 0; k < K; ++k)
            EXPECT_LT(std::abs(gradient[k]), 1e-9 * scale) << "k = " << k << ", sigma_a = " << c.sigmaA;
    }
}

// A profile that has all but vanished by rho (z_r = 1 / sigma_t' = 0.09 mm, rho = 2 mm): the self term
// carries all its light, the fit gives the transfer next to nothing, while the plain
// projection's coefficients are of order one and multiply every matrix's compression error.
TEST(ProfileProjection, AProfileInsideTheDiskLeavesTheTransferNothing) {
    const ProfileBasis& basis = bakeLikeBasis();
    const DipoleCoefficients narrow{basis.range().sigmaSPrimeMax, basis.range().sigmaAMax, 1.3};
    const std::vector<double> plain = basis.coefficients(narrow);
    const std::vector<double> fitted = ProfileProjection(basis, 2.0).coefficients(narrow);
    double plainNorm = 0.0, fittedNorm = 0.0;
    for (std::size_t k = 0; k < plain.size(); ++k) {
        plainNorm = std::max(plainNorm, std::abs(plain[k]));
        fittedNorm = std::max(fittedNorm, std::abs(fitted[k]));
    }
    std::printf("[ fit ] narrowest material, rho 2 mm: max |s_k| plain %.3e, fitted beyond the disk %.3e\n", plainNorm,
                fittedNorm);
    EXPECT_LT(fittedNorm, 1e-3 * plainNorm);
}

TEST(ProfileProjection, RejectsBadInput) {
    const ProfileBasis& basis = bakeLikeBasis();
    EXPECT_THROW(ProfileProjection(basis, -1.0), Error);
    EXPECT_THROW(ProfileProjection(basis, std::nan("")), Error);
    EXPECT_THROW(ProfileProjection(ProfileBasis{}, 1.0), Error);
    const ProfileProjection fit(basis, 1.0);
    EXPECT_THROW(fit.coefficients({-1.0, 0.1, 1.3}), Error);
    EXPECT_THROW(fit.coefficients({1.0, 0.1, 5.0}), Error);
}

}  // namespace
}  // namespace opal
