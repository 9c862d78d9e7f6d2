// The engine's compression sweep (bench/compression_sweep.h): which settings it bakes, and
// that each bake matches the asset it stands beside in everything but compression.
#include "bench/compression_sweep.h"

#include <gtest/gtest.h>

#include <vector>

namespace opal::bench {
namespace {

TEST(CompressionSweep, CountsAtTheDefaultEnergyThenEnergiesAtTheShippedBudgetEachOnce) {
    const TransferSettings d;
    const std::vector<std::uint32_t> perRows = {32, 512, 32};
    const std::vector<double> energies = {0.999, d.energyFraction, 0.999};
    const std::vector<TransferSettings> s = compressionSettings(perRows, energies);
    ASSERT_EQ(s.size(), 4u);
    EXPECT_EQ(s[0].minPerRow, 32u);
    EXPECT_LT(s[0].keepFraction * 65536.0, 1.0);  // the count governs at every sample count
    EXPECT_EQ(s[0].energyFraction, d.energyFraction);
    EXPECT_EQ(s[1].minPerRow, 512u);
    EXPECT_EQ(s[2].keepFraction, d.keepFraction);
    EXPECT_EQ(s[2].minPerRow, d.minPerRow);
    EXPECT_EQ(s[2].energyFraction, 0.999);
    EXPECT_EQ(s[3].energyFraction, d.energyFraction);  // the shipped defaults
    EXPECT_EQ(s[3].keepFraction, d.keepFraction);
}

TEST(CompressionSweep, BakesMatchTheAssetButForCompression) {
    TranslucentAsset asset;
    asset.samples.resize(1024);
    asset.unitsPerMm = 0.25;
    asset.bake.scheme = "loop";
    asset.bake.level = 2;
    asset.bake.seed = 7;
    asset.bake.envTerms = 64;
    asset.environment.offsets = {0, 0};
    asset.environment.cubeFaceSize = 16;
    asset.environment.fresnelTerms = 3;
    asset.range = {0.1, 9.0, 0.001, 0.5, 1.25, 1.5};
    const BakeOptions o = sweepBakeOptions(asset, "mesh.obj", {0.05, 0.999});
    EXPECT_EQ(o.input, "mesh.obj");
    EXPECT_EQ(o.samples, 1024u);
    EXPECT_EQ(o.unitsPerMm, 0.25);
    EXPECT_EQ(o.scheme, "loop");
    EXPECT_EQ(o.level, 2u);
    EXPECT_EQ(o.seed, 7u);
    EXPECT_EQ(o.visibility.terms, 64u);
    EXPECT_EQ(o.visibility.cubeFaceSize, 16u);
    EXPECT_EQ(o.visibility.fresnelTerms, 3u);
    ASSERT_TRUE(o.range);
    EXPECT_EQ(o.range->sigmaSPrimeMax, 9.0);
    EXPECT_EQ(o.range->etaMin, 1.25);
    EXPECT_EQ(o.transfer.keepFraction, 0.05);
    EXPECT_EQ(o.transfer.energyFraction, 0.999);
}

}  // namespace
}  // namespace opal::bench
