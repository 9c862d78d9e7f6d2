// The coefficients s_k(sigma) a relighter weighs the transfer matrices with, when the
// transfer uses the profile only beyond the samples' own disks (docs/ARCHITECTURE.md#pca,
// "Fit beyond the self disk"). The self term covers r < rho exactly, so the fit need not
// reproduce the profile's peak there; the s_k multiply the compressed T_k's errors, so
// they are kept small where T_k is compressed coarsely (step 2 weighs matrix k by
// lambda_k / lambda_1); and the far tail, a thousandth of the peak and less, is what a
// sample lit only from afar receives, so it is fitted for its relative error too:
//
//     s0 = argmin  sum_{l: r_l >= rho} w_l m_l (R_d(r_l) - sum_k s_k b_k(r_l))^2
//                + mu sum_k (lambda_1 / lambda_k) s_k^2,                      mu = 1e-5
//
//     m_l = 1 for r_l < r_t = 4 rho, else  max(1, min(x^-1/2, x^1/2 / f)),
//           x = R_d(r_l) / R_d(r_t),  f = 1e-4
//
// (the emphasis grows as the profile falls, to 100 where it is 1e-4 of its value at r_t,
// and falls back to 1 where it is 1e-8: there the profile has vanished and a squared
// error hardly counts), subject to one constraint: where the profile has vanished
// (x < f^2, the nodes V) the fit carries the dipole's light, no more,
//
//     sum_{l in V} w_l sum_k s_k b_k(r_l) = sum_{l in V} w_l R_d(r_l)        (a . s = t)
//
// (a bias there of a ten-millionth of the peak, summed over the hundreds of square
// centimetres of a large object, is a percent of a dim sample's light), then the nearest
// nonnegative profile (ProfileBasis::nonnegative). rho = 0 is the plain
// projection, ProfileBasis::coefficients, bit for bit (no ridge, no emphasis): what assets
// whose transfer holds the self term need.
#pragma once

#include "schema/scatter/profile_basis.h"

#include <array>
#include <vector>

namespace opal {

class ProfileProjection {
public:
    static constexpr double kRidge = 1e-5;      // mu
    static constexpr double kTailStart = 4.0;   // r_t / rho
    static constexpr double kTailFloor = 1e-4;  // f

    // m(x) above for x = R_d(r) / R_d(r_t); 1 for x that is not positive and finite.
    static double tailEmphasis(double x);

    // innerRadius rho in mm. The basis must outlive the projection. Throws opal::Error for
    // an empty basis or a negative or NaN radius.
    ProfileProjection(const ProfileBasis& basis, double innerRadius);

    double innerRadius() const { return rho_; }
    // Same preconditions as ProfileBasis::coefficients.
    std::vector<double> coefficients(const DipoleCoefficients& c) const;
    // s0 alone, before the nonnegative step (the constraint on the vanished tail holds).
    std::vector<double> unconstrainedCoefficients(const DipoleCoefficients& c) const;
    std::array<std::vector<double>, 3> project(const Material& m) const;

private:
    const ProfileBasis* basis_;
    double rho_ = 0.0;
    std::size_t first_ = 0;      // the first node with r_l >= rho
    std::size_t tail_ = 0;       // the first node with r_l >= r_t (L when none)
    std::vector<double> ridge_;  // mu lambda_1 / lambda_k; empty when rho = 0
};

}  // namespace opal
