// Where a pixel's sub-pixel samples fall (docs/ARCHITECTURE.md#image-formation): the
// Owen-scrambled Sobol (0,2)-sequence in base 2, the same for every pixel, so a render is
// the same whatever the thread count. Any first 2^m samples are stratified in every
// elementary interval of area 2^-m (16 samples: one in each cell of a 4 x 4 grid, of a 2 x 8
// grid, ...), so every pass leaves a well-spread estimate.
//
// The scramble is a fixed seed chosen among 20,000 for the smallest worst-case error of 16
// samples on a straight edge (box filter, every orientation, every offset through the
// pixel): 0.122 of a pixel's area, 0.094 on average over orientations; within one sample's
// weight plus 2% (0.0825) for edges near the axes and at 10-20 degrees from them.
// tests/render/sample_pattern_test.cpp measures all of it against exact areas.
#pragma once

#include <Imath/ImathVec.h>

#include <cstdint>

namespace opal {

// Sample k of a pixel, in [0, 1)^2 from the pixel's top-left corner (x right, y down).
Imath::V2f samplePosition(std::uint32_t k);

}  // namespace opal
