#include "schema/scatter/dipole.h"

#include "schema/error.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

namespace opal {

namespace {

// One pole of the dipole: z (sigma_tr + 1/d) e^{-sigma_tr d} / d^2 with d = sqrt(r^2 + z^2).
double poleTerm(double r, double z, double sigmaTr) {
    const double d = std::hypot(r, z);
    return z * (sigmaTr + 1.0 / d) * std::exp(-sigmaTr * d) / (d * d);
}

// integral_0^rho z (sigma_tr + 1/d) e^{-sigma_tr d}/d^2 r dr, one pole: with d dd = r dr
// the integrand is -d/dd (z e^{-sigma_tr d}/d).
double poleDiskIntegral(double rho, double z, double sigmaTr) {
    const double d = std::hypot(rho, z);
    const double far = std::isinf(rho) ? 0.0 : z * std::exp(-sigmaTr * d) / d;
    return std::max(0.0, std::exp(-sigmaTr * z) - far);  // >= 0; rounding near radius 0
}

// The dipole's sources for one channel (docs/ARCHITECTURE.md#coefficients and #poles, with
// the corrected sigma_t' and sigma_tr): real source at depth z_r = 1/sigma_t', virtual one at
// z_v = z_r (1 + 4A/3).
struct Poles {
    double alphaPrime, sigmaTr, zr, zv;
};

Poles poles(const DipoleCoefficients& c) {
    const double sigmaTPrime = c.sigmaSPrime + c.sigmaA;
    const double zr = 1.0 / sigmaTPrime;
    return {c.sigmaSPrime / sigmaTPrime, std::sqrt(3.0 * c.sigmaA * sigmaTPrime), zr,
            zr * (1.0 + 4.0 * boundaryMismatch(c.eta) / 3.0)};
}

}  // namespace

void requireDipoleEta(double eta, std::string_view context) {
    if (eta >= kDipoleEtaMin && eta <= kDipoleEtaMax) return;  // false for NaN
    std::ostringstream out;
    out << context << ": eta = " << eta << " lies outside [" << kDipoleEtaMin << ", " << kDipoleEtaMax
        << "], the range where the dipole's boundary term A(eta) is valid (its diffuse Fresnel fit reaches 1 "
           "near eta = 3.85, where A diverges)";
    throw Error(out.str());
}

void requireDipoleCoefficients(const DipoleCoefficients& c, std::string_view context) {
    const bool valid = std::isfinite(c.sigmaSPrime) && c.sigmaSPrime > 0.0 && std::isfinite(c.sigmaA) &&
                       c.sigmaA > 0.0;
    if (!valid) {
        std::ostringstream out;
        out << context << ": sigmaSPrime = " << c.sigmaSPrime << ", sigmaA = " << c.sigmaA
            << ": coefficients must be positive and finite";
        throw Error(out.str());
    }
    requireDipoleEta(c.eta, context);
}

// A = (1 + F_dr) / (1 - F_dr): the boundary mismatch term (docs/ARCHITECTURE.md#boundary).
double boundaryMismatch(double eta) {
    const double fdr = fresnelDiffuseReflectance(eta);
    return (1.0 + fdr) / (1.0 - fdr);
}

// F_dr(eta), Egan and Hilgeman's polynomial fit (docs/ARCHITECTURE.md#boundary).
double fresnelDiffuseReflectance(double eta) {
    return -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta;
}

// The paper's equation (4) as Jensen et al. 2001 give it (docs/ARCHITECTURE.md#dipole):
// R_d(r) = alpha'/(4 pi) [z_r (sigma_tr + 1/d_r) e^{-sigma_tr d_r}/d_r^2
//                       + z_v (sigma_tr + 1/d_v) e^{-sigma_tr d_v}/d_v^2].
double dipoleProfile(double r, const DipoleCoefficients& c) {
    const Poles p = poles(c);
    return p.alphaPrime / (4.0 * std::numbers::pi) * (poleTerm(r, p.zr, p.sigmaTr) + poleTerm(r, p.zv, p.sigmaTr));
}

// integral_0^radius R_d(r) 2 pi r dr = (alpha'/(4 pi)) 2 pi (sum over both poles).
double dipoleDiskReflectance(double radius, const DipoleCoefficients& c) {
    const Poles p = poles(c);
    return 0.5 * p.alphaPrime * (poleDiskIntegral(radius, p.zr, p.sigmaTr) + poleDiskIntegral(radius, p.zv, p.sigmaTr));
}

// docs/ARCHITECTURE.md#total-reflectance: integral_0^inf R_d(r) 2 pi r dr
//   = (alpha'/2) (1 + e^{-(4/3) A sqrt(3(1-alpha'))}) e^{-sqrt(3(1-alpha'))}.
double dipoleTotalReflectance(double alphaPrime, double eta) {
    const double s = std::sqrt(3.0 * (1.0 - alphaPrime));
    const double a = boundaryMismatch(eta);
    return 0.5 * alphaPrime * (1.0 + std::exp(-4.0 / 3.0 * a * s)) * std::exp(-s);
}

// Unpolarized Fresnel transmittance 1 - (r_s^2 + r_p^2)/2 from index 1 into index eta,
// with cos(theta_t) from Snell's law (total internal reflection when eta < 1).
double fresnelTransmittance(double eta, double cosTheta) {
    if (!(eta > 0.0) || !std::isfinite(eta) || std::isnan(cosTheta))
        throw Error("fresnelTransmittance: eta must be positive and finite and cos(theta) a number, got eta = " +
                    std::to_string(eta) + ", cos(theta) = " + std::to_string(cosTheta));
    if (eta == 1.0) return 1.0;
    const double cosI = std::clamp(cosTheta, 0.0, 1.0);
    const double sin2T = (1.0 - cosI * cosI) / (eta * eta);
    if (sin2T >= 1.0) return 0.0;
    const double cosT = std::sqrt(1.0 - sin2T);
    const double rs = (cosI - eta * cosT) / (cosI + eta * cosT);
    const double rp = (eta * cosI - cosT) / (eta * cosI + cosT);
    return 1.0 - 0.5 * (rs * rs + rp * rp);
}

}  // namespace opal
