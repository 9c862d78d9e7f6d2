// The figures of bench/image_accuracy.h and the targets of bench/accuracy_targets.h as
// JSON, one spelling for every subcommand that reports them (`accuracy`, `compare`).
#pragma once

#include "bench/accuracy_targets.h"
#include "bench/image_accuracy.h"
#include "schema/scatter/material.h"

#include <nlohmann/json.hpp>

#include <string>

namespace opal::bench {

using Json = nlohmann::ordered_json;

// pixels, measured_pixels, relative_rmse, luminance_error, darker_half_luminance_error,
// chromaticity_error (each {median, p95}), negative_fraction, deepest_negative.
Json accuracyJson(const ImageAccuracy& a);
Json targetsJson(const AccuracyTargets& t);
// name, sigma_s_prime, sigma_a, eta and mean_free_path_mm (RGB arrays, per mm and mm).
Json materialJson(const std::string& name, const Material& m);

}  // namespace opal::bench
