#include "delegate/relight/light_emission.h"

#include "schema/error.h"
#include "schema/scatter/blackbody.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace opal {

namespace {

std::string describe(const hd::LightDesc& d) {
    std::ostringstream text;
    text.precision(6);
    text << "inputs:intensity " << d.intensity << " x 2^(inputs:exposure " << d.exposure << ") x inputs:color (" << d.color.x
         << ", " << d.color.y << ", " << d.color.z << ")";
    if (d.enableColorTemperature) text << " x black body (inputs:colorTemperature " << d.colorTemperature << " K)";
    return text.str();
}

bool finiteNonNegative(double v) { return std::isfinite(v) && v >= 0.0; }

}  // namespace

Rgb emittedRadiance(const hd::LightDesc& d) {
    if (!finiteNonNegative(d.intensity) || !std::isfinite(d.exposure) || !finiteNonNegative(d.color.x) ||
        !finiteNonNegative(d.color.y) || !finiteNonNegative(d.color.z))
        throw Error(describe(d) + ": intensity and color must be finite and non-negative, exposure finite");
    // exp2 of a huge exposure is +inf in double: the product check below catches it (an
    // exposure far below zero underflows to 0, a dark light).
    Rgb color = d.color;
    if (d.enableColorTemperature) {
        if (!(d.colorTemperature >= 500.0 && d.colorTemperature <= 40000.0))
            throw Error(describe(d) + ": inputs:colorTemperature must be within 500 to 40000 K");
        const Imath::V3d body = blackbodyAcescg(d.colorTemperature);
        color = Rgb(color.x * body.x, color.y * body.y, color.z * body.z);
    }
    const Rgb le = color * (d.intensity * std::exp2(d.exposure));
    if (!(std::max({le.x, le.y, le.z}) <= kMaxEmittedRadiance)) {
        std::ostringstream bound;
        bound << kMaxEmittedRadiance;
        throw Error(describe(d) + " exceeds " + bound.str() + ", the largest emitted radiance Opal renders");
    }
    return le;
}

}  // namespace opal
