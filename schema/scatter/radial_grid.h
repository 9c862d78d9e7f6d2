// The radial samples r_l and quadrature weights w_l = 2 pi r_l dr_l of the PCA profile
// basis (docs/ARCHITECTURE.md#pca).
#pragma once

#include <vector>

namespace opal {

struct RadialGrid {
    std::vector<double> radii;    // r_l in mm, increasing, radii.front() = 0, radii.back() = rMax
    std::vector<double> weights;  // w_l in mm^2: sum_l w_l f(r_l) ~= integral_0^rMax f(r) 2 pi r dr
};

// r(u) = r0 ((1 + rMax/r0)^u - 1) at u_l = l / (samples - 1): spacing about r0 near 0 and
// geometric (a constant fraction of r) beyond, so profiles of every scale from r0 to rMax
// get the same number of samples. Weights are the trapezoid rule in u:
// w_l = 2 pi r(u_l) r'(u_l) du, halved at both ends. Throws opal::Error for rMax or r0 not
// positive and finite, or fewer than 2 samples.
RadialGrid makeRadialGrid(double rMax, double r0, int samples);

}  // namespace opal
