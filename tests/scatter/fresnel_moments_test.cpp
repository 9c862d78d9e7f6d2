// The Fresnel-moment fit of F_t(eta, mu) (schema/scatter/fresnel_moments.h) in both bases,
// against F_t itself on a fine grid: the Schlick basis bakes use fits 3 to 10 times closer
// than the Legendre basis of older assets, with the same number of terms.
#include "schema/error.h"
#include "schema/scatter/dipole.h"
#include "schema/scatter/fresnel_moments.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace opal {
namespace {

struct FitError {
    double weightedRms = 0.0;  // sqrt(int (fit - F_t)^2 mu dmu / int F_t^2 mu dmu)
    double worst = 0.0;        // max |fit - F_t| / F_t over mu >= 0.1
};

FitError fitError(double eta, int terms, FresnelBasis basis) {
    const std::vector<double> c = fresnelMoments(eta, terms, basis);
    const int nodes = 4000;
    double num = 0.0, den = 0.0;
    FitError e;
    for (int q = 0; q < nodes; ++q) {
        const double mu = (q + 0.5) / nodes, ft = fresnelTransmittance(eta, mu);
        double fit = 0.0;
        for (int m = 0; m < terms; ++m) fit += c[std::size_t(m)] * fresnelBasisFunction(basis, m, mu);
        num += mu * (fit - ft) * (fit - ft);
        den += mu * ft * ft;
        if (mu >= 0.1) e.worst = std::max(e.worst, std::abs(fit - ft) / ft);
    }
    e.weightedRms = std::sqrt(num / den);
    return e;
}

TEST(FresnelMoments, TheSchlickBasisFitsFtSeveralTimesCloserThanLegendre) {
    for (double eta : {1.1, 1.3, 1.5, 1.8, 2.5}) {
        const FitError schlick = fitError(eta, 2, FresnelBasis::Schlick);
        const FitError legendre = fitError(eta, 2, FresnelBasis::Legendre);
        std::printf("eta %.1f, two terms: Schlick RMS %.4f worst %.3f; Legendre RMS %.4f worst %.3f\n", eta,
                    schlick.weightedRms, schlick.worst, legendre.weightedRms, legendre.worst);
        EXPECT_LT(schlick.weightedRms, 0.02) << eta;
        EXPECT_LT(schlick.worst, 0.06) << eta;  // 5.6% at eta 1.1, 2.1% at 1.3
        EXPECT_LT(schlick.weightedRms, 0.35 * legendre.weightedRms) << eta;
        EXPECT_LT(fitError(eta, 3, FresnelBasis::Schlick).weightedRms, schlick.weightedRms * 1.0001) << eta;
    }
}

// The fit keeps the hemisphere's mean: with P_0 = 1 in the mu-weighted least squares, the
// residual is orthogonal to 1, so a uniform dome gets the exact integral of F_t mu.
TEST(FresnelMoments, BothBasesKeepTheCosineWeightedMean) {
    for (FresnelBasis basis : {FresnelBasis::Legendre, FresnelBasis::Schlick})
        for (double eta : {1.0, 1.3, 1.6}) {
            const std::vector<double> c = fresnelMoments(eta, 2, basis);
            const int nodes = 20000;
            double fit = 0.0, exact = 0.0;
            for (int q = 0; q < nodes; ++q) {
                const double mu = (q + 0.5) / nodes;
                for (int m = 0; m < 2; ++m) fit += mu * c[std::size_t(m)] * fresnelBasisFunction(basis, m, mu) / nodes;
                exact += mu * fresnelTransmittance(eta, mu) / nodes;
            }
            EXPECT_NEAR(fit, exact, 2e-4 * exact) << int(basis) << ' ' << eta;
        }
}

TEST(FresnelMoments, BasisFunctionsAreBoundedAndOrdersChecked) {
    for (FresnelBasis basis : {FresnelBasis::Legendre, FresnelBasis::Schlick})
        for (int m = 0; m < kMaxFresnelTerms; ++m)
            for (double mu = 0.0; mu <= 1.0; mu += 0.01) EXPECT_LE(std::abs(fresnelBasisFunction(basis, m, mu)), 1.0);
    EXPECT_THROW(fresnelBasisFunction(FresnelBasis::Schlick, 3, 0.5), Error);
    EXPECT_THROW(fresnelMoments(1.3, 4, FresnelBasis::Schlick), Error);
}

}  // namespace
}  // namespace opal
