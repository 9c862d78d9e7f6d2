// F_t(eta, mu) expanded in shifted Legendre polynomials of mu = cos(theta) on [0, 1]:
//   F_t(eta, mu) ~= sum_m c_m(eta) P_m(mu),  P_0 = 1, P_1 = 2mu - 1, P_2 = 6mu^2 - 6mu + 1.
// The bake stores environment transport vectors V mu P_m(mu) dOmega for each m; at run time
// E = sum_m c_m(eta) <T_m, L>, so an edit of eta needs no new visibility
// (docs/ARCHITECTURE.md#fresnel-moments).
#pragma once

#include <vector>

namespace opal {

inline constexpr int kMaxFresnelTerms = 3;

double shiftedLegendre(int m, double mu);

// The c_m minimizing integral_0^1 (F_t(eta, mu) - sum_m c_m P_m(mu))^2 mu dmu: the
// cosine-weighted least-squares fit, since the irradiance integral weights by mu.
std::vector<double> fresnelMoments(double eta, int terms);

}  // namespace opal
