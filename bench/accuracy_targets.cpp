#include "bench/accuracy_targets.h"

#include <cstdio>

namespace opal::bench {

namespace {

void check(std::vector<std::string>& missed, const char* figure, double value, double limit) {
    if (value <= limit) return;
    char text[96];
    std::snprintf(text, sizeof text, "%s %.4g > %.4g", figure, value, limit);
    missed.push_back(text);
}

}  // namespace

std::vector<std::string> missedTargets(const ImageAccuracy& a, const AccuracyTargets& targets) {
    std::vector<std::string> missed;
    check(missed, "rel.RMSE", a.relativeRmse, targets.relativeRmse);
    check(missed, "Y p95", a.luminance.p95, targets.luminanceP95);
    check(missed, "chr p95", a.chromaticity.p95, targets.chromaticityP95);
    check(missed, "negative", a.negativeFraction, targets.negativeFraction);
    return missed;
}

}  // namespace opal::bench
