#include "bake/energy_histogram.h"

#include "schema/error.h"

#include <bit>
#include <algorithm>
#include <cmath>
#include <string>

namespace opal {

namespace {

constexpr int kBinShift = 19;
constexpr int kMantissaBits = 23;

}  // namespace

int energyBin(float e) { return int(std::bit_cast<std::uint32_t>(e) >> kBinShift); }
float binLowerEdge(int bin) { return std::bit_cast<float>(std::uint32_t(bin) << kBinShift); }

EnergyHistogram::EnergyHistogram() : sums_(kEnergyBins, 0) {}

void EnergyHistogram::add(float e) {
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(e);
    const std::uint32_t exponent = bits >> kMantissaBits;
    const std::uint32_t mantissa = bits & ((1u << kMantissaBits) - 1);
    sums_[bits >> kBinShift] += exponent ? (mantissa | (1u << kMantissaBits)) : mantissa;
}

void EnergyHistogram::add(const EnergyHistogram& other) {
    for (int b = 0; b < kEnergyBins; ++b) sums_[b] += other.sums_[b];
}

double EnergyHistogram::binEnergy(int bin) const {
    // The bin's exponent field: its top 8 of 12 bits (bins carry no sign: energies are >= 0).
    const int exponent = bin >> (kMantissaBits - kBinShift);
    return std::ldexp(double(sums_[bin]), std::max(exponent, 1) - 127 - kMantissaBits);
}

double EnergyHistogram::total() const {
    double total = 0.0;
    for (int b = 0; b < kEnergyBins; ++b) total += binEnergy(b);
    return total;
}

int EnergyHistogram::thresholdBin(double fraction) const {
    if (fraction >= 1.0) return 0;
    const double goal = fraction * total();
    double kept = 0.0;
    for (int b = kEnergyBins - 1; b >= 0; --b) {
        kept += binEnergy(b);
        if (kept >= goal) return b;
    }
    return 0;
}

double EnergyHistogram::fractionFrom(int minBin) const {
    double kept = 0.0;
    for (int b = minBin; b < kEnergyBins; ++b) kept += binEnergy(b);
    const double all = total();
    return all > 0.0 ? kept / all : 1.0;
}

std::vector<std::uint64_t> EnergyHistogram::words() const {
    std::vector<std::uint64_t> out;
    out.reserve(2 * sums_.size());
    for (Sum s : sums_) {
        out.push_back(std::uint64_t(s));
        out.push_back(std::uint64_t(s >> 64));
    }
    return out;
}

EnergyHistogram EnergyHistogram::fromWords(std::span<const std::uint64_t> words) {
    if (words.size() != 2 * std::size_t(kEnergyBins))
        throw Error("energy histogram: " + std::to_string(words.size()) + " words, expected " +
                    std::to_string(2 * kEnergyBins));
    EnergyHistogram h;
    for (int b = 0; b < kEnergyBins; ++b) h.sums_[b] = (Sum(words[2 * b + 1]) << 64) | words[2 * b];
    return h;
}

}  // namespace opal
