// F_t(eta, mu) expanded in a few functions of mu = cos(theta) on [0, 1]:
//   F_t(eta, mu) ~= sum_m c_m(eta) P_m(mu)
// with P_m from one of two bases:
//   Legendre (assets baked before the Schlick basis): P_0 = 1, P_1 = 2mu - 1, P_2 = 6mu^2 - 6mu + 1
//   Schlick (what bakes write):                       P_0 = 1, P_1 = (1 - mu)^5, P_2 = (1 - mu)^2
// Schlick's approximation F_r ~= F_0 + (1 - F_0)(1 - mu)^5 says why the second fits F_t:
// at eta = 1.3 the two-term fit's mu-weighted RMS error is 0.64% (Legendre: 6.8%) and its
// worst relative error for mu >= 0.1 is 2.1% (Legendre: 59%).
// The bake stores environment transport vectors V mu P_m(mu) dOmega for each m; at run time
// E = sum_m c_m(eta) <T_m, L>, so an edit of eta needs no new visibility
// (docs/ARCHITECTURE.md#fresnel-moments).
#pragma once

#include <cstdint>
#include <vector>

namespace opal {

inline constexpr int kMaxFresnelTerms = 3;

// Stored in sidecars (chunk FBAS): the values are frozen.
enum class FresnelBasis : std::uint32_t { Legendre = 0, Schlick = 1 };

double shiftedLegendre(int m, double mu);
// P_m(mu) of `basis`, |P_m| <= 1 on [0, 1]. Throws opal::Error for m outside [0, 3).
double fresnelBasisFunction(FresnelBasis basis, int m, double mu);

// The c_m minimizing integral_0^1 (F_t(eta, mu) - sum_m c_m P_m(mu))^2 mu dmu: the
// cosine-weighted least-squares fit, since the irradiance integral weights by mu.
std::vector<double> fresnelMoments(double eta, int terms, FresnelBasis basis = FresnelBasis::Legendre);

}  // namespace opal
