// R_d of one channel as a function of the squared distance, with the r-independent terms
// computed once (docs/ARCHITECTURE.md#dipole): the form the gathers evaluate N^2 times.
//   R_d(r) = alpha'/(4 pi) [z_r (sigma_tr + 1/d_r) e^{-sigma_tr d_r}/d_r^2
//                         + z_v (sigma_tr + 1/d_v) e^{-sigma_tr d_v}/d_v^2]
// Same values as dipoleProfile (up to rounding); same preconditions (validateMaterial).
#pragma once

#include "schema/scatter/dipole.h"

#include <cmath>
#include <numbers>

namespace opal {

class DipoleProfile {
public:
    explicit DipoleProfile(const DipoleCoefficients& c) {
        const double sigmaTPrime = c.sigmaSPrime + c.sigmaA;
        scale_ = c.sigmaSPrime / sigmaTPrime / (4.0 * std::numbers::pi);
        sigmaTr_ = std::sqrt(3.0 * c.sigmaA * sigmaTPrime);
        zr_ = 1.0 / sigmaTPrime;
        zv_ = zr_ * (1.0 + 4.0 * boundaryMismatch(c.eta) / 3.0);
    }
    // r2: the squared distance in mm^2; returns mm^-2.
    double operator()(double r2) const { return scale_ * (pole(r2, zr_) + pole(r2, zv_)); }

private:
    double pole(double r2, double z) const {
        const double d2 = r2 + z * z, d = std::sqrt(d2);
        return z * (sigmaTr_ + 1.0 / d) * std::exp(-sigmaTr_ * d) / d2;
    }
    double scale_ = 0.0, sigmaTr_ = 0.0, zr_ = 0.0, zv_ = 0.0;
};

}  // namespace opal
