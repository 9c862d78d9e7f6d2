// Scaled binary16: how the delegate's working copies of baked data (transfer_product.h,
// environment_vectors.h) halve their memory traffic. A set of values v is stored as the
// IEEE binary16 of v 2^-e, with e putting the largest |v| in (2^14, 2^15] (as the sidecar's
// half planes do), so every stored value keeps 11 significant bits (relative rounding
// <= 2^-11). Values whose half would be subnormal (below 2^-28 of the largest) are not
// stored: at most 2^-28 of the largest each.
#pragma once

#include "schema/asset/array_codec.h"  // halfScaleExponent: the same e as the sidecar's half planes

#include <cstdint>

namespace opal {

// The binary16 bits of v 2^-e when that is a normal half; false for zero, subnormal or
// non-finite results (callers drop the first two and reject the last).
bool toNormalHalf(float v, int e, std::uint16_t& bits);

// The float a normal binary16 bit pattern stands for (exponent field 1 to 30; what
// toNormalHalf stores): re-bias the 5-bit exponent (15) to float's (127) and widen the
// 10-bit mantissa. Integer operations only, no table and no F16C.
inline float normalHalfToFloat(std::uint16_t h) {
    const std::uint32_t bits = (std::uint32_t(h & 0x8000u) << 16) | ((std::uint32_t(h & 0x7fffu) << 13) + (112u << 23));
    float f;
    __builtin_memcpy(&f, &bits, sizeof f);
    return f;
}

// normalHalfToFloat, or 0 for the zero half (what the transfer product's slots hold where
// one matrix of a pair has no entry).
inline float storedHalfToFloat(std::uint16_t h) { return (h & 0x7fffu) != 0 ? normalHalfToFloat(h) : 0.0f; }

}  // namespace opal
