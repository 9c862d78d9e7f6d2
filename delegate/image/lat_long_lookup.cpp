#include "delegate/image/lat_long_lookup.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace opal {

namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

float fastAtan2(float y, float x) {
    const float ax = std::abs(x), ay = std::abs(y);
    const float mx = std::max(ax, ay), mn = std::min(ax, ay);
    if (mx == 0.0f) return 0.0f;
    const float t = mn / mx, z = t * t;
    // atan(t), t in [0, 1]: odd minimax polynomial, |error| ~1e-5 rad.
    float a = t * (0.99997726f +
                   z * (-0.33262347f + z * (0.19354346f + z * (-0.11643287f + z * (0.05265332f + z * -0.01172120f)))));
    if (ay > ax) a = float(kPi / 2.0) - a;
    if (x < 0.0f) a = float(kPi) - a;
    return y < 0.0f ? -a : a;
}

Imath::V2f latLongCoordinates(const Imath::V3f& d) {
    const float theta = fastAtan2(d.y, std::sqrt(d.x * d.x + d.z * d.z));
    const float phi = fastAtan2(d.x, d.z);
    constexpr float kInversePi = float(1.0 / kPi);
    return {0.5f * (1.0f - phi * kInversePi), 0.5f - theta * kInversePi};
}

}  // namespace opal
