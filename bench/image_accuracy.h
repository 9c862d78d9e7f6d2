// How close an engine image is to its exact reference, as `opal-bench accuracy` reports it
// (issue 13's figures), over the pixels that show the asset:
//   relativeRmse   sqrt(sum |a - b|^2 / sum |b|^2) over RGB
//   luminance      |Y(a) - Y(b)| / Y(b) per pixel, over the pixels whose reference Y is at
//                  least 1% of the 99th percentile of the asset's Y (dimmer ones are noise
//                  against nothing): median and 95th percentile, and the same over the
//                  darker half of those pixels (by reference Y)
//   chromaticity   the L1 distance between (r, g) / (r + g + b) of engine and reference,
//                  same pixels: median and 95th percentile
//   negative       the fraction of the asset's pixels with a channel below 0 in the engine,
//                  and the deepest such channel as a fraction of the 99th percentile of the
//                  asset's reference Y (how far below zero, next to how often)
// Y uses the working space's luminance weights (ACEScg's by default).
#pragma once

#include "schema/scatter/rgb.h"  // kAcescgLuminance

#include <Imath/ImathVec.h>

#include <cstdint>
#include <span>
#include <vector>

namespace opal::bench {

struct Percentiles {
    double median = 0.0, p95 = 0.0;
};

struct ImageAccuracy {
    std::size_t pixels = 0;        // the asset's pixels
    std::size_t measured = 0;      // of those, bright enough for the per-pixel figures
    double relativeRmse = 0.0;
    Percentiles luminance, darkerHalf, chromaticity;
    double negativeFraction = 0.0;
    double deepestNegative = 0.0;  // min(0, lowest engine channel) / p99 of reference Y
};

// engine, reference: RGB per pixel (3 floats each, same size); mask: 1 where the pixel
// shows the asset. Throws opal::Error for sizes that do not match or an empty mask.
ImageAccuracy measureAccuracy(std::span<const float> engine, std::span<const float> reference,
                              std::span<const std::uint8_t> mask, const Imath::V3d& luminance = kAcescgLuminance);

// The same over every pixel (or per-sample values, a sample a pixel).
ImageAccuracy measureAccuracy(std::span<const float> engine, std::span<const float> reference,
                              const Imath::V3d& luminance = kAcescgLuminance);

// The p-th percentile (p in [0, 1]) of `values` by nearest rank on the sorted values; 0
// for none. Reorders `values`.
double percentile(std::span<double> values, double p);

}  // namespace opal::bench
