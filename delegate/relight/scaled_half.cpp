#include "delegate/relight/scaled_half.h"

#include <Imath/half.h>

#include <cmath>

namespace opal {

namespace {

constexpr float kSmallestNormalHalf = 6.103515625e-05f;  // 2^-14

}  // namespace

bool toNormalHalf(float v, int e, std::uint16_t& bits) {
    const float scaled = std::ldexp(v, -e);
    if (!std::isfinite(scaled)) return false;
    const Imath::half h(scaled);
    if (!(std::abs(float(h)) >= kSmallestNormalHalf) || h.isInfinity()) return false;
    bits = h.bits();
    return true;
}

}  // namespace opal
