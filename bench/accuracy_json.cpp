#include "bench/accuracy_json.h"

#include "bench/mean_free_path_ends.h"

namespace opal::bench {

namespace {
Json percentilesJson(const Percentiles& p) { return {{"median", p.median}, {"p95", p.p95}}; }
Json rgbJson(const Rgb& c) { return Json::array({c[0], c[1], c[2]}); }
}  // namespace

Json accuracyJson(const ImageAccuracy& a) {
    return {{"pixels", a.pixels},
            {"measured_pixels", a.measured},
            {"relative_rmse", a.relativeRmse},
            {"luminance_error", percentilesJson(a.luminance)},
            {"darker_half_luminance_error", percentilesJson(a.darkerHalf)},
            {"chromaticity_error", percentilesJson(a.chromaticity)},
            {"negative_fraction", a.negativeFraction},
            {"deepest_negative", a.deepestNegative}};
}

Json targetsJson(const AccuracyTargets& t) {
    return {{"relative_rmse", t.relativeRmse},
            {"luminance_error_p95", t.luminanceP95},
            {"chromaticity_error_p95", t.chromaticityP95},
            {"negative_fraction", t.negativeFraction}};
}

Json materialJson(const std::string& name, const Material& m) {
    return {{"name", name},
            {"sigma_s_prime", rgbJson(m.sigmaSPrime)},
            {"sigma_a", rgbJson(m.sigmaA)},
            {"eta", m.eta},
            {"mean_free_path_mm", rgbJson(meanFreePath(m))}};
}

}  // namespace opal::bench
