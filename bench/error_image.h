// The picture of an engine image's error against its reference, as `opal-bench accuracy`
// and `opal-bench compare` write it: |Y(a) - Y(b)| / Y(b) as grey, 0 black and 5% or more
// white (the per-pixel target is 3%); pixels outside the mask dark blue. Display-referred,
// for writePreview.
#pragma once

#include "delegate/output/image.h"

#include <cstdint>
#include <span>

namespace opal::bench {

// engine, reference: RGB per pixel, rows from the top; mask: 1 where the pixel is measured.
// Throws opal::Error for sizes that do not match width x height.
Image luminanceErrorImage(int width, int height, std::span<const float> engine, std::span<const float> reference,
                          std::span<const std::uint8_t> mask);

}  // namespace opal::bench
