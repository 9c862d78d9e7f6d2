// How an analytic light enters the Fresnel-moment irradiance (irradiance.h,
// docs/ARCHITECTURE.md#fresnel-moments).
//
// The engine weights the moments with c_m(eta) = fresnelMoments(eta, terms, basis), the
// cosine-weighted fit of F_t(eta, .) in the asset's basis P_m, so that baked environment vectors
// (V mu P_m(mu) dw) give E = sum_m c_m <T_m, L>. That fit is good on average over the
// hemisphere but not per direction: a light from one direction mu with E_m = E_perp mu
// P_m(mu) would be off by up to 5-6% (2 or 3 terms, eta = 1.3).
//
// Analytic lights therefore use response functions h_m(mu) chosen so that
//     sum_m c_m(eta) h_m(mu) ~= F_t(eta, mu)   for every eta in [etaMin, etaMax]
// (for each mu, least squares over eta), and deliver E_m = E_perp mu h_m(mu). The
// coefficients c_m stay those of the environment transfer, so every light sums into the
// same moments. With the default editable range [1.2, 1.6]: 2 terms give 4e-4 RMS error
// and < 1% for mu >= 0.1; 3 terms 1e-5 RMS; 1 term 0.8% RMS, 9% at mu = 0.1.
#pragma once

#include "schema/scatter/fresnel_moments.h"

#include <vector>

namespace opal {

class FresnelResponse {
public:
    // Throws opal::Error unless 1 <= etaMin <= etaMax (finite) and terms is in [1, 3].
    FresnelResponse(double etaMin, double etaMax, int terms, FresnelBasis basis = FresnelBasis::Legendre);

    int terms() const { return terms_; }
    // h[m] = h_m(mu) for m < terms, mu clamped to [0, 1] (linear between table nodes).
    void evaluate(double mu, float* h) const;

private:
    int terms_ = 0;
    std::vector<float> table_;  // (kNodes + 1) x terms over mu = j / kNodes
};

}  // namespace opal
