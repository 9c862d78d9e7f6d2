#include "delegate/image/sample_pattern.h"

namespace opal {

namespace {

// The seed's two dimensions (hashes of seed 430; sample_pattern.h says how it was chosen).
constexpr std::uint32_t kScrambleX = 2833738457u, kScrambleY = 40703801u;

std::uint32_t reverseBits(std::uint32_t v) {
    v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
    v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
    v = ((v >> 4) & 0x0F0F0F0Fu) | ((v & 0x0F0F0F0Fu) << 4);
    v = ((v >> 8) & 0x00FF00FFu) | ((v & 0x00FF00FFu) << 8);
    return (v >> 16) | (v << 16);
}

// Sobol's second dimension: direction numbers v_0 = 2^31, v_{j+1} = v_j ^ (v_j >> 1).
std::uint32_t sobolY(std::uint32_t k) {
    std::uint32_t result = 0;
    for (std::uint32_t v = 1u << 31; k != 0; k >>= 1, v ^= v >> 1)
        if (k & 1u) result ^= v;
    return result;
}

// Nested uniform (Owen) scrambling by Laine and Karras's hash: each bit flipped by a hash of
// the bits above it, which keeps every elementary interval holding one point.
std::uint32_t owenScramble(std::uint32_t v, std::uint32_t seed) {
    v = reverseBits(v);
    v += seed;
    v ^= v * 0x6c50b47cu;
    v ^= v * 0xb82f1e52u;
    v ^= v * 0xc7afe638u;
    v ^= v * 0x8d22f6e6u;
    return reverseBits(v);
}

float unitFloat(std::uint32_t bits) { return float(bits >> 8) * (1.0f / 16777216.0f); }  // [0, 1), 24 bits

}  // namespace

Imath::V2f samplePosition(std::uint32_t k) {
    return {unitFloat(owenScramble(reverseBits(k), kScrambleX)), unitFloat(owenScramble(sobolY(k), kScrambleY))};
}

}  // namespace opal
