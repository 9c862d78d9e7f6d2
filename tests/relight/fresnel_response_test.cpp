#include "delegate/relight/fresnel_response.h"

#include "schema/error.h"
#include "schema/scatter/dipole.h"
#include "schema/scatter/fresnel_moments.h"

#include <gtest/gtest.h>

#include <cmath>

namespace opal {
namespace {

struct FitError {
    double rms = 0.0;           // relative, over the (eta, mu) grid, mu-weighted
    double maxRelative = 0.0;   // for mu >= 0.1
};

// sum_m c_m(eta) h_m(mu) against the exact F_t(eta, mu) on a grid finer than the fit's.
FitError fitError(const FresnelResponse& response, double etaMin, double etaMax) {
    FitError e;
    double diff = 0.0, norm = 0.0;
    float h[kMaxFresnelTerms];
    for (int j = 0; j <= 40; ++j) {
        const double eta = etaMin + (etaMax - etaMin) * j / 40.0;
        const std::vector<double> c = fresnelMoments(eta, response.terms());
        for (int q = 0; q < 500; ++q) {
            const double mu = (q + 0.5) / 500.0;
            response.evaluate(mu, h);
            double f = 0.0;
            for (int m = 0; m < response.terms(); ++m) f += c[m] * h[m];
            const double exact = fresnelTransmittance(eta, mu);
            diff += mu * (f - exact) * (f - exact);
            norm += mu * exact * exact;
            if (mu >= 0.1) e.maxRelative = std::max(e.maxRelative, std::abs(f - exact) / exact);
        }
    }
    e.rms = std::sqrt(diff / norm);
    return e;
}

TEST(FresnelResponse, ReproducesTheExactTransmittanceOverTheEtaRange) {
    const FitError two = fitError(FresnelResponse(1.2, 1.6, 2), 1.2, 1.6);
    EXPECT_LT(two.rms, 1e-3);
    EXPECT_LT(two.maxRelative, 0.012);
    const FitError three = fitError(FresnelResponse(1.2, 1.6, 3), 1.2, 1.6);
    EXPECT_LT(three.rms, 5e-5);
    EXPECT_LT(three.maxRelative, 1e-3);
    // A single eta is matched exactly by one term.
    const FitError single = fitError(FresnelResponse(1.33, 1.33, 1), 1.33, 1.33);
    EXPECT_LT(single.maxRelative, 1e-4);
}

TEST(FresnelResponse, BeatsTheLegendreMomentsForOneDirection) {
    // The plain moment form h_m = P_m is off by several percent at normal incidence.
    const double eta = 1.4;
    const std::vector<double> c = fresnelMoments(eta, 2);
    const double legendre = c[0] * shiftedLegendre(0, 1.0) + c[1] * shiftedLegendre(1, 1.0);
    EXPECT_GT(std::abs(legendre / fresnelTransmittance(eta, 1.0) - 1.0), 0.03);
    float h[2];
    FresnelResponse(1.2, 1.6, 2).evaluate(1.0, h);
    EXPECT_NEAR((c[0] * h[0] + c[1] * h[1]) / fresnelTransmittance(eta, 1.0), 1.0, 2e-3);
}

TEST(FresnelResponse, RejectsBadInput) {
    EXPECT_THROW(FresnelResponse(0.9, 1.5, 2), Error);
    EXPECT_THROW(FresnelResponse(1.5, 1.2, 2), Error);
    EXPECT_THROW(FresnelResponse(1.2, 1.5, 4), Error);
}

}  // namespace
}  // namespace opal
