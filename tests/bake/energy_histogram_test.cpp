// Step 2's energy histogram (bake/energy_histogram.h): sums that do not depend on the
// order or the split of the additions (what lets a farm of any shard count keep exactly
// the plain bake's coefficients), against double sums and a long double reference.
#include "bake/energy_histogram.h"
#include "schema/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace opal {
namespace {

std::vector<float> energies() {
    std::mt19937 rng(7);
    std::lognormal_distribution<float> size(0.0f, 3.0f);
    std::vector<float> e(200000);
    for (float& v : e) v = size(rng);
    return e;
}

EnergyHistogram inChunks(const std::vector<float>& e, std::size_t chunks) {
    EnergyHistogram all;
    for (std::size_t c = 0; c < chunks; ++c) {
        EnergyHistogram part;
        for (std::size_t i = e.size() * c / chunks; i < e.size() * (c + 1) / chunks; ++i) part.add(e[i]);
        all.add(part);
    }
    return all;
}

TEST(EnergyHistogram, AnyOrderAndSplitGivesTheSameSums) {
    std::vector<float> e = energies();
    // The inputs are such that a plain double sum over all of them depends on the order.
    double forward = 0.0, backward = 0.0;
    for (float v : e) forward += v;
    for (auto v = e.rbegin(); v != e.rend(); ++v) backward += *v;
    ASSERT_NE(forward, backward);

    const std::vector<std::uint64_t> one = inChunks(e, 1).words();
    EXPECT_EQ(inChunks(e, 3).words(), one);
    EXPECT_EQ(inChunks(e, 7).words(), one);
    std::reverse(e.begin(), e.end());
    EXPECT_EQ(inChunks(e, 1).words(), one);
    EXPECT_EQ(EnergyHistogram::fromWords(one).words(), one);
}

TEST(EnergyHistogram, ThresholdAndKeptFractionMatchALongDoubleReference) {
    const std::vector<float> e = energies();
    EnergyHistogram h;
    long double total = 0.0L;
    for (float v : e) {
        h.add(v);
        total += v;
    }
    for (double fraction : {0.5, 0.9, 0.999}) {
        const int bin = h.thresholdBin(fraction);
        long double kept = 0.0L, above = 0.0L;
        for (float v : e) {
            if (energyBin(v) >= bin) kept += v;
            if (energyBin(v) > bin) above += v;
        }
        // The lowest bin whose inclusion reaches the fraction.
        EXPECT_GE(kept, fraction * total) << fraction;
        EXPECT_LT(above, fraction * total) << fraction;
        EXPECT_NEAR(h.fractionFrom(bin), double(kept / total), 1e-12) << fraction;
        EXPECT_LE(binLowerEdge(bin), *std::min_element(e.begin(), e.end(), [&](float a, float b) {
            return (energyBin(a) >= bin ? a : INFINITY) < (energyBin(b) >= bin ? b : INFINITY);
        }));
    }
    EXPECT_EQ(h.thresholdBin(1.0), 0);
    EXPECT_EQ(EnergyHistogram().fractionFrom(5), 1.0);
}

TEST(EnergyHistogram, SubnormalAndZeroEnergiesAreCounted) {
    EnergyHistogram h;
    const float tiny = std::ldexp(1.0f, -140);  // subnormal
    h.add(tiny);
    h.add(0.0f);
    const float normal = std::ldexp(1.0f, -120);
    h.add(normal);
    EXPECT_EQ(h.thresholdBin(0.5), energyBin(normal));
    EXPECT_EQ(h.thresholdBin(1.0 - 1e-7), energyBin(tiny));
    EXPECT_NEAR(h.fractionFrom(energyBin(normal)), 1.0 / (1.0 + std::ldexp(1.0, -20)), 1e-15);
    EXPECT_EQ(h.fractionFrom(0), 1.0);
    EXPECT_THROW(EnergyHistogram::fromWords(std::vector<std::uint64_t>(3)), Error);
}

}  // namespace
}  // namespace opal
