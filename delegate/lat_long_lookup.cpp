#include "delegate/lat_long_lookup.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace opal {

namespace {

constexpr double kPi = std::numbers::pi;

// Cephes atan.c (Moshier): atan(x) = x + x z P(z) / Q(z), z = x^2, for |x| <= 0.66.
constexpr double P[5] = {-8.750608600031904122785e-1, -1.615753718733365076637e1, -7.500855792314704667340e1,
                         -1.228866684490136173410e2, -6.485021904942025371773e1};
constexpr double Q[5] = {2.485846490142306297962e1, 1.650270098316988542046e2, 4.328810604912902668951e2,
                         4.853903996359136964868e2, 1.945506571482613964425e2};
constexpr double kMoreBits = 6.123233995736765886130e-17;  // pi/2 - double(pi/2)

// atan(mn / mx) for 0 <= mn <= mx, mx > 0, with one division for the argument: the
// rational form directly for a ratio up to 0.66, else pi/4 + atan((mn - mx) / (mn + mx)).
double atanOfRatio(double mn, double mx) {
    const bool shifted = mn > 0.66 * mx;
    const double x = shifted ? (mn - mx) / (mn + mx) : mn / mx;
    const double z = x * x;
    const double p = (((P[0] * z + P[1]) * z + P[2]) * z + P[3]) * z + P[4];
    const double q = ((((z + Q[0]) * z + Q[1]) * z + Q[2]) * z + Q[3]) * z + Q[4];
    const double r = x * (z * p / q) + x;
    return shifted ? kPi / 4.0 + (r + 0.5 * kMoreBits) : r;
}

}  // namespace

double fastAtan2(double y, double x) {
    const double ax = std::abs(x), ay = std::abs(y);
    if (ax == 0.0 && ay == 0.0) return std::atan2(y, x);  // the signed-zero cases
    // atan(ay / ax) = pi/2 - atan(ax / ay): the ratio stays in [0, 1].
    double a = ay <= ax ? atanOfRatio(ay, ax) : kPi / 2.0 - (atanOfRatio(ax, ay) - kMoreBits);
    if (std::signbit(x)) a = kPi - a;
    return std::signbit(y) ? -a : a;
}

Imath::V2d latLongCoordinates(const Imath::V3d& d) {
    const double theta = fastAtan2(d.y, std::sqrt(d.x * d.x + d.z * d.z));
    const double phi = fastAtan2(d.x, d.z);
    constexpr double kInversePi = 1.0 / kPi;
    return {0.5 * (1.0 - phi * kInversePi), 0.5 - theta * kInversePi};
}

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
