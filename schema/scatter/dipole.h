// The Jensen et al. 2001 dipole diffusion profile and the Fresnel terms it needs.
// All lengths in millimetres, coefficients in mm^-1 (DESIGN.md section 2; the seed
// paper's equation (4) has typos, these are the corrected formulas).
#pragma once

namespace opal {

// One color channel of a homogeneous scattering medium.
struct DipoleCoefficients {
    double sigmaSPrime = 1.0;  // reduced scattering coefficient sigma_s' = (1-g) sigma_s [mm^-1]
    double sigmaA = 0.01;      // absorption coefficient [mm^-1]
    double eta = 1.3;          // relative index of refraction (inside / outside)
};

// F_dr(eta) = -1.440/eta^2 + 0.710/eta + 0.668 + 0.0636 eta  (Egan and Hilgeman fit).
double fresnelDiffuseReflectance(double eta);

// R_d(r): diffuse reflectance profile at distance r [mm], in mm^-2. No checks (a hot
// function): c must hold positive finite coefficients and eta >= 1 (validateMaterial).
double dipoleProfile(double r, const DipoleCoefficients& c);

// integral_0^inf R_d(r) 2 pi r dr in closed form, a function of alpha' and eta only.
double dipoleTotalReflectance(double alphaPrime, double eta);

// integral_0^radius R_d(r) 2 pi r dr in closed form: the light a disk of that radius
// around the point of incidence gathers (d/dd of -e^{-sigma_tr d}/d is the integrand
// of each pole, so each pole integrates to e^{-sigma_tr z} - z e^{-sigma_tr d}/d with
// d = sqrt(radius^2 + z^2)):
//   (alpha'/2) sum_{z in {z_r, z_v}} [e^{-sigma_tr z} - z e^{-sigma_tr d(z)} / d(z)].
// The transfer's self term (DESIGN.md section 5): a sample gathers its own light over its
// own area A, a disk of radius sqrt(A / pi), not at the profile's peak R_d(0) times A.
// radius = infinity gives dipoleTotalReflectance. Same preconditions as dipoleProfile.
double dipoleDiskReflectance(double radius, const DipoleCoefficients& c);

// Exact unpolarized dielectric Fresnel transmittance 1 - F_r for light arriving from
// outside (index 1) onto a medium of index eta, at incidence cos(theta) in [0, 1].
// cos(theta) is clamped into [0, 1]; eta = 1 gives 1; eta < 1 gives 0 beyond the critical
// angle. Throws opal::Error for eta not positive and finite or cos(theta) NaN.
double fresnelTransmittance(double eta, double cosTheta);

}  // namespace opal
