// Step 2's energy histogram (transfer_stages.h): the weighted energies of all 9/7
// coefficients of a bake, binned by the top bits of their float representation (for
// positive floats the bit pattern is monotonic, so bins are ordered, 1/8 octave each).
// Every energy in a bin has the same float exponent, so a bin's sum is kept exactly, as
// the integer sum of the energies' significands: adding histograms is then associative,
// and the threshold cannot depend on how the columns were split into blocks, tasks or
// threads (a plain bake and a farm bake of 1, 3 or 7 shards keep the same coefficients).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace opal {

inline constexpr int kEnergyBins = 1 << 12;

int energyBin(float e);
float binLowerEdge(int bin);

class EnergyHistogram {
public:
    EnergyHistogram();

    // e must be finite and non-negative.
    void add(float e);
    void add(const EnergyHistogram& other);

    // The lowest bin kept so that the kept energy reaches `fraction` of the total (0 for
    // fraction >= 1 or an empty histogram).
    int thresholdBin(double fraction) const;
    // The fraction of the total energy in bins >= minBin (1 for an empty histogram).
    double fractionFrom(int minBin) const;

    // Per bin, the exact significand sum as (low, high) 64-bit words: what a task file
    // stores. fromWords rejects a span of the wrong size.
    std::vector<std::uint64_t> words() const;
    static EnergyHistogram fromWords(std::span<const std::uint64_t> words);

private:
    double binEnergy(int bin) const;  // rounded once from the exact sum
    double total() const;

    __extension__ typedef unsigned __int128 Sum;
    std::vector<Sum> sums_;  // per bin, sum of significands in units of the bin's last place
};

}  // namespace opal
