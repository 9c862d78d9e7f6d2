// A small counter-based random number generator. Bakes must be reproducible: the same
// seed gives the same samples on every platform and under any TBB scheduling, so each
// work item draws from its own stream (seed, item index) and the mapping to [0, 1) is
// ours, not std::uniform_real_distribution's (whose output is implementation-defined).
#pragma once

#include <cstdint>

namespace opal {

// SplitMix64 (Steele, Lea, Flood 2014): one 64-bit state, full period, good avalanche.
class Random {
public:
    Random(std::uint64_t seed, std::uint64_t stream)
        : state_(mix(seed ^ mix(stream + 0x632be59bd9b4e019ull))) {}

    std::uint64_t nextBits() {
        state_ += 0x9e3779b97f4a7c15ull;
        return mix(state_);
    }

    // Uniform in [0, 1): the top 24 bits scaled by 2^-24, so 1.0f is never returned.
    float uniformFloat() { return float(nextBits() >> 40) * 0x1p-24f; }

    // Uniform in [0, 1) with 53 random bits.
    double uniformDouble() { return double(nextBits() >> 11) * 0x1p-53; }

private:
    static std::uint64_t mix(std::uint64_t z) {
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }

    std::uint64_t state_;
};

}  // namespace opal
