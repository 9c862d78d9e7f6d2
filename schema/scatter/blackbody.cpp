#include "schema/scatter/blackbody.h"

#include "schema/scatter/acescg_from_xyz.h"

#include "schema/error.h"

#include <cmath>
#include <string>

namespace opal {
namespace {

// Piecewise Gaussian: exp(-(lambda - mu)^2 / (2 sigma^2)), sigma1 left of mu, sigma2 right.
double lobe(double lambda, double mu, double sigma1, double sigma2) {
    const double s = (lambda - mu) / (lambda < mu ? sigma1 : sigma2);
    return std::exp(-0.5 * s * s);
}

// Wyman, Sloan, Shirley 2013, "Simple Analytic Approximations to the CIE XYZ Color
// Matching Functions", multi-lobe fit (lambda in nm).
Imath::V3d colourMatching(double l) {
    const double x = 1.056 * lobe(l, 599.8, 37.9, 31.0) + 0.362 * lobe(l, 442.0, 16.0, 26.7) -
                     0.065 * lobe(l, 501.1, 20.4, 26.2);
    const double y = 0.821 * lobe(l, 568.8, 46.9, 40.5) + 0.286 * lobe(l, 530.9, 16.3, 31.1);
    const double z = 1.217 * lobe(l, 437.0, 11.8, 36.0) + 0.681 * lobe(l, 459.0, 26.0, 13.8);
    return {x, y, z};
}

// Planck's law up to a constant factor (only the colour matters).
double planck(double lambdaNm, double kelvin) {
    constexpr double hcOverK = 1.438776877e-2;  // h c / k, m K
    const double lambda = lambdaNm * 1e-9;
    return 1.0 / (std::pow(lambdaNm * 1e-3, 5.0) * std::expm1(hcOverK / (lambda * kelvin)));
}

Imath::V3d blackbodyXyz(double kelvin) {
    if (!(kelvin >= 500.0 && kelvin <= 40000.0))
        throw Error("colour temperature " + std::to_string(kelvin) + " K is outside [500, 40000] K");
    Imath::V3d xyz(0.0);
    for (int l = 380; l <= 780; ++l) xyz += colourMatching(l) * planck(l, kelvin);
    return xyz;
}

}  // namespace

Imath::V2d blackbodyChromaticity(double kelvin) {
    const Imath::V3d xyz = blackbodyXyz(kelvin);
    const double sum = xyz.x + xyz.y + xyz.z;
    return {xyz.x / sum, xyz.y / sum};
}

Imath::V3d blackbodyAcescg(double kelvin) {
    const Imath::V3d rgb = transform(kXyzD65ToAcescg, blackbodyXyz(kelvin));
    return rgb / rgb.dot(kAcescgLuminance);
}

}  // namespace opal
