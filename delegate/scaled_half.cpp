#include "delegate/scaled_half.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>

namespace opal {

namespace {

constexpr int kHalfTopExponent = 15;                     // the largest |v| 2^-e lands in (2^14, 2^15]
constexpr float kSmallestNormalHalf = 6.103515625e-05f;  // 2^-14

}  // namespace

int halfScaleExponent(std::span<const float> values) {
    float largest = 0.0f;
    for (float v : values) largest = std::max(largest, std::abs(v));
    if (largest == 0.0f || !std::isfinite(largest)) return 0;
    int exponent = 0;
    const float mantissa = std::frexp(largest, &exponent);
    return (mantissa == 0.5f ? exponent - 1 : exponent) - kHalfTopExponent;
}

bool toNormalHalf(float v, int e, std::uint16_t& bits) {
    const float scaled = std::ldexp(v, -e);
    if (!std::isfinite(scaled)) return false;
    const Imath::half h(scaled);
    if (!(std::abs(float(h)) >= kSmallestNormalHalf) || h.isInfinity()) return false;
    bits = h.bits();
    return true;
}

}  // namespace opal
