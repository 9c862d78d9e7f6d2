// How a pixel's samples are weighted (docs/ARCHITECTURE.md#image-formation). The filter
// covers the pixel only: a sample counts for the pixel it falls in, with weight w(x) w(y)
// at its position (x, y) in [0, 1)^2, and a filtered AOV is sum w_i v_i / sum w_i.
//   box              w = 1: the pixel's average (alpha = the covered fraction)
//   blackmanHarris   the 4-term Blackman-Harris window across the pixel: sharper, more
//                    weight at the centre, less at the edges
#pragma once

#include <Imath/ImathVec.h>

#include <span>
#include <string>
#include <string_view>

namespace opal {

enum class PixelFilter { Box, BlackmanHarris };

float filterWeight(PixelFilter filter, const Imath::V2f& position);

// "box", "blackmanHarris"; parse throws opal::Error naming the valid ones.
std::span<const std::string_view> pixelFilterNames();
std::string_view pixelFilterName(PixelFilter filter);
PixelFilter parsePixelFilter(std::string_view name);

}  // namespace opal
