#include "schema/scatter/material_sampler.h"

#include "schema/error.h"

#include <cmath>
#include <random>
#include <string>

namespace opal {

namespace {

// The top 53 bits of one 64-bit draw, scaled to [0, 1): identical on every platform,
// unlike std::uniform_real_distribution whose algorithm is implementation-defined.
double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

double logUniform(std::mt19937_64& rng, double lo, double hi) {
    return lo * std::exp(uniform01(rng) * std::log(hi / lo));
}

}  // namespace

std::vector<DipoleCoefficients> sampleChannels(const EditableRange& range, int count, std::uint64_t seed) {
    range.validate("sampleChannels");
    if (count < 0) throw Error("sampleChannels: count = " + std::to_string(count) + " must not be negative");
    std::mt19937_64 rng(seed);
    std::vector<DipoleCoefficients> channels(static_cast<std::size_t>(count));
    for (DipoleCoefficients& c : channels) {
        c.sigmaSPrime = logUniform(rng, range.sigmaSPrimeMin, range.sigmaSPrimeMax);
        c.sigmaA = logUniform(rng, range.sigmaAMin, range.sigmaAMax);
        c.eta = range.etaMin + uniform01(rng) * (range.etaMax - range.etaMin);
    }
    return channels;
}

}  // namespace opal
