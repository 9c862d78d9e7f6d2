// Issue 13's accuracy targets for one engine image against its exact reference
// (bench/image_accuracy.h's figures), and which of them an image misses.
#pragma once

#include "bench/image_accuracy.h"

#include <string>
#include <vector>

namespace opal::bench {

struct AccuracyTargets {
    double relativeRmse = 0.01;       // image relative RMSE
    double luminanceP95 = 0.03;       // 95th percentile of the per-pixel relative luminance error
    double chromaticityP95 = 0.005;   // no visible hue noise
    double negativeFraction = 0.0;    // no negative radiance
};

// The targets `a` misses, each as "figure value > limit" (empty: it passes). A figure
// equal to its limit meets it.
std::vector<std::string> missedTargets(const ImageAccuracy& a, const AccuracyTargets& targets);

}  // namespace opal::bench
