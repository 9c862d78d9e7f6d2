#include "schema/scatter/radial_grid.h"

#include "schema/error.h"

#include <cmath>
#include <numbers>
#include <string>

namespace opal {

RadialGrid makeRadialGrid(double rMax, double r0, int samples) {
    if (!std::isfinite(rMax) || !(rMax > 0.0) || !std::isfinite(r0) || !(r0 > 0.0))
        throw Error("makeRadialGrid: rMax = " + std::to_string(rMax) + " mm and r0 = " + std::to_string(r0) +
                    " mm must be positive and finite");
    if (samples < 2) throw Error("makeRadialGrid: samples = " + std::to_string(samples) + " must be at least 2");
    const double logRatio = std::log1p(rMax / r0);
    const double du = 1.0 / (samples - 1);
    RadialGrid grid;
    grid.radii.resize(samples);
    grid.weights.resize(samples);
    for (int l = 0; l < samples; ++l) {
        const double r = (l == samples - 1) ? rMax : r0 * std::expm1(l * du * logRatio);
        const double drdu = (r + r0) * logRatio;
        const double trapezoid = (l == 0 || l == samples - 1) ? 0.5 : 1.0;
        grid.radii[l] = r;
        grid.weights[l] = 2.0 * std::numbers::pi * r * drdu * du * trapezoid;
    }
    return grid;
}

}  // namespace opal
