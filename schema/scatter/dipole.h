// The Jensen et al. 2001 dipole diffusion profile and the Fresnel terms it needs.
// All lengths in millimetres, coefficients in mm^-1 (docs/ARCHITECTURE.md#dipole; the seed
// paper's equation (4) has typos, these are Jensen et al. 2001's formulas).
#pragma once

#include <string_view>

namespace opal {

// The relative index of refraction the dipole accepts: [1, 3]. The boundary term
// A(eta) = (1 + F_dr)/(1 - F_dr) uses Egan and Hilgeman's polynomial F_dr, which reaches 1
// near eta = 3.85, where A diverges and then turns negative (z_v behind the surface). Up
// to 2.5 the fit's A stays within 5% of the exact hemispherical integral's; at 3 it is 26%
// high (A = 30.0 against 23.9) and the error grows quickly beyond (82 against 35 at 3.5),
// so 3 is where the fit still means something, with A finite and positive. Below 1 the
// fit's F_dr turns negative (A < 1, and A < 0 at 0.5), and light arriving from outside
// meets total internal reflection, which the dipole does not model. The presets' 1.3 and
// water to diamond (1.33-2.42) lie inside.
inline constexpr double kDipoleEtaMin = 1.0;
inline constexpr double kDipoleEtaMax = 3.0;

// The one check of eta every entry point uses (materials, the artist conversion, editable
// ranges, the dipole gather, scene overrides). Throws opal::Error
// "<context>: eta = <value> lies outside [1, 3], where the dipole's boundary term is valid
// (...)" for NaN, infinities and values outside [kDipoleEtaMin, kDipoleEtaMax].
void requireDipoleEta(double eta, std::string_view context);

// One color channel of a homogeneous scattering medium.
struct DipoleCoefficients {
    double sigmaSPrime = 1.0;  // reduced scattering coefficient sigma_s' = (1-g) sigma_s [mm^-1]
    double sigmaA = 0.01;      // absorption coefficient [mm^-1]
    double eta = 1.3;          // relative index of refraction (inside / outside)
};

// F_dr(eta) = -1.440/eta^2 + 0.710/eta + 0.668 + 0.0636 eta  (Egan and Hilgeman fit).
double fresnelDiffuseReflectance(double eta);

// A(eta) = (1 + F_dr)/(1 - F_dr): the boundary mismatch term; finite, >= 1 and
// increasing on [kDipoleEtaMin, kDipoleEtaMax]. Unchecked.
double boundaryMismatch(double eta);

// Throws opal::Error "<context>: sigmaSPrime = .., sigmaA = ..: coefficients must be positive
// and finite" unless both are, and requireDipoleEta's error for eta.
void requireDipoleCoefficients(const DipoleCoefficients& c, std::string_view context);

// R_d(r): diffuse reflectance profile at distance r [mm], in mm^-2. No checks (a hot
// function): c must hold positive finite coefficients and eta in [1, 3] (validateMaterial).
double dipoleProfile(double r, const DipoleCoefficients& c);

// integral_0^inf R_d(r) 2 pi r dr in closed form, a function of alpha' and eta only.
double dipoleTotalReflectance(double alphaPrime, double eta);

// integral_0^radius R_d(r) 2 pi r dr in closed form: the light a disk of that radius
// around the point of incidence gathers (d/dd of -e^{-sigma_tr d}/d is the integrand
// of each pole, so each pole integrates to e^{-sigma_tr z} - z e^{-sigma_tr d}/d with
// d = sqrt(radius^2 + z^2)):
//   (alpha'/2) sum_{z in {z_r, z_v}} [e^{-sigma_tr z} - z e^{-sigma_tr d(z)} / d(z)].
// The transfer's self term (docs/ARCHITECTURE.md#total-reflectance): a sample gathers its own light
// over its own area A, a disk of radius sqrt(A / pi), not at the profile's peak R_d(0) times A.
// radius = infinity gives dipoleTotalReflectance. Same preconditions as dipoleProfile.
double dipoleDiskReflectance(double radius, const DipoleCoefficients& c);

// Exact unpolarized dielectric Fresnel transmittance 1 - F_r for light arriving from
// outside (index 1) onto a medium of index eta, at incidence cos(theta) in [0, 1].
// cos(theta) is clamped into [0, 1]; eta = 1 gives 1; eta < 1 gives 0 beyond the critical
// angle. Throws opal::Error for eta not positive and finite or cos(theta) NaN.
double fresnelTransmittance(double eta, double cosTheta);

}  // namespace opal
