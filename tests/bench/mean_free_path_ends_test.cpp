// The ends of an editable range by mean free path (bench/mean_free_path_ends.h): the closed
// form 1 / (sigma_s' + sigma_a) at the box's corners, and no point of the box beyond them.
#include "bench/mean_free_path_ends.h"

#include "schema/error.h"

#include <gtest/gtest.h>

namespace opal::bench {
namespace {

// An asymmetric box, so that a corner mixed up with another shows.
EditableRange box() { return {0.5, 8.0, 0.002, 0.3, 1.2, 1.6}; }

TEST(MeanFreePathEnds, ShortestIsBothCoefficientsAtTheirMaximum) {
    const Material m = shortestMeanFreePath(box(), 1.3);
    for (int c = 0; c < 3; ++c) {
        EXPECT_DOUBLE_EQ(meanFreePath(m)[c], 1.0 / (8.0 + 0.3));
        EXPECT_DOUBLE_EQ(m.sigmaSPrime[c], 8.0);
        EXPECT_DOUBLE_EQ(m.sigmaA[c], 0.3);
    }
    EXPECT_EQ(m.eta, 1.3);
    EXPECT_TRUE(box().contains(m));
}

TEST(MeanFreePathEnds, LongestIsBothCoefficientsAtTheirMinimum) {
    const Material m = longestMeanFreePath(box(), 1.45);
    for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(meanFreePath(m)[c], 1.0 / (0.5 + 0.002));
    EXPECT_EQ(m.eta, 1.45);
    EXPECT_TRUE(box().contains(m));
}

TEST(MeanFreePathEnds, NoMaterialOfTheBoxLiesBeyondTheEnds) {
    const EditableRange r = box();
    const double shortest = meanFreePath(shortestMeanFreePath(r, 1.3))[0];
    const double longest = meanFreePath(longestMeanFreePath(r, 1.3))[0];
    for (int i = 0; i <= 20; ++i)
        for (int j = 0; j <= 20; ++j) {
            const double s = r.sigmaSPrimeMin + (r.sigmaSPrimeMax - r.sigmaSPrimeMin) * i / 20.0;
            const double a = r.sigmaAMin + (r.sigmaAMax - r.sigmaAMin) * j / 20.0;
            const double ell = 1.0 / (s + a);
            EXPECT_GE(ell, shortest * (1 - 1e-12)) << s << " " << a;
            EXPECT_LE(ell, longest * (1 + 1e-12)) << s << " " << a;
        }
}

TEST(MeanFreePathEnds, MaterialsByNameAreTheDefaultAndTheEnds) {
    TranslucentAsset asset;
    asset.range = box();
    asset.defaultMaterial = {Rgb{1.0, 1.5, 2.0}, Rgb{0.01, 0.02, 0.03}, 1.3};
    const Material byDefault = materialNamed("default", asset);
    EXPECT_EQ(byDefault.sigmaSPrime[1], 1.5);
    EXPECT_EQ(byDefault.sigmaA[2], 0.03);
    EXPECT_EQ(meanFreePath(materialNamed("short", asset))[0], meanFreePath(shortestMeanFreePath(box(), 1.3))[0]);
    EXPECT_EQ(meanFreePath(materialNamed("long", asset))[0], meanFreePath(longestMeanFreePath(box(), 1.3))[0]);
    EXPECT_EQ(materialNamed("long", asset).eta, 1.3);
}

TEST(MeanFreePathEnds, EtaOutsideTheRangeIsAnError) {
    EXPECT_THROW(shortestMeanFreePath(box(), 1.7), Error);
    EXPECT_THROW(longestMeanFreePath(EditableRange{}, 1.3), Error);  // empty intervals
}

}  // namespace
}  // namespace opal::bench
