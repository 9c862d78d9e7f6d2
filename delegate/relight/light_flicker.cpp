#include "delegate/relight/light_flicker.h"

#include "schema/error.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace opal {

namespace {

// A lattice value in [-1, 1] from (seed, stream, integer position): SplitMix64's finalizer.
double latticeValue(std::uint64_t seed, std::uint64_t stream, std::int64_t i) {
    std::uint64_t z = seed * 0x9E3779B97F4A7C15ull + stream * 0xBF58476D1CE4E5B9ull + std::uint64_t(i);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return double(z >> 11) * (2.0 / 9007199254740992.0) - 1.0;  // 53 bits -> [-1, 1)
}

// Smoothstep-interpolated value noise, one octave.
double valueNoise(std::uint64_t seed, std::uint64_t stream, double x) {
    const double cell = std::floor(x);
    const double u = x - cell, s = u * u * (3.0 - 2.0 * u);
    const std::int64_t i = std::int64_t(cell);
    return latticeValue(seed, stream, i) * (1.0 - s) + latticeValue(seed, stream, i + 1) * s;
}

// Two octaves, normalised back to [-1, 1].
double noise(std::uint64_t seed, std::uint64_t stream, double x) {
    return (valueNoise(seed, stream, x) + 0.5 * valueNoise(seed, stream + 17, 2.0 * x + 0.37)) / 1.5;
}

}  // namespace

FlickerState lightFlicker(const hd::LightFlicker& flicker, double time) {
    if (!std::isfinite(flicker.amplitude) || flicker.amplitude < 0.0 || !std::isfinite(flicker.frequency) ||
        flicker.frequency < 0.0)
        throw Error("flicker: amplitude " + std::to_string(flicker.amplitude) + " and frequency " +
                    std::to_string(flicker.frequency) + " must be finite and >= 0");
    if (!std::isfinite(time)) throw Error("flicker: the scene time is not finite");
    FlickerState state;
    if (flicker.amplitude == 0.0) return state;
    // Bounded so that the lattice index stays far inside int64 for any finite input.
    const double x = std::clamp(flicker.frequency * time, -1e15, 1e15);
    const std::uint64_t seed = flicker.seed;
    const double a = flicker.amplitude;
    state.intensity = std::max(0.0, 1.0 + a * noise(seed, 0, x));
    state.offset = Imath::V3d(noise(seed, 1, x), 0.5 * noise(seed, 2, x), noise(seed, 3, x)) * (a / 4.0);
    return state;
}

}  // namespace opal
