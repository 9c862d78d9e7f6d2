// 2D orthonormal Haar wavelet, nonstandard decomposition (Stollnitz, DeRose and Salesin),
// in place on a row-major size x size grid, size a power of two. Used for the light
// dimension of the transfer (step 1, "w0") and for environment maps and visibility.
//
// Each level does one Haar step along every row of the active s x s block, then one
// along every column, and recurses on the low-low quadrant down to 1 x 1 (size 1 is the
// identity). Coefficients end in the Mallat quadrant layout: the overall average
// (scaled) at [0], the level-s details in the three quadrants [0, s/2) x [s/2, s),
// [s/2, s) x [0, s/2) and [s/2, s)^2 (row x column). The step is
//   low = (a + b) / sqrt(2),  high = (a - b) / sqrt(2),
// so the transform is orthonormal: energy is preserved and the inverse is the transpose.
//
// `channels` values per cell are stored interleaved (cell-major) and transformed
// independently. Bad input (size not a power of two, span size mismatch) throws
// opal::Error. Explicitly instantiated for float and double.
#pragma once

#include "schema/wavelet/chart_layout.h"

#include <cstdint>
#include <span>
#include <vector>

namespace opal {

template <typename T>
void haarForward2D(std::span<T> grid, std::uint32_t size, std::uint32_t channels = 1);
template <typename T>
void haarInverse2D(std::span<T> grid, std::uint32_t size, std::uint32_t channels = 1);

// The same on every chart of a layout (data.size() == layout.cells() * channels), in
// parallel over charts when the data is large.
template <typename T>
void haarForwardCharts(std::span<T> data, const ChartLayout& layout, std::uint32_t channels = 1);
template <typename T>
void haarInverseCharts(std::span<T> data, const ChartLayout& layout, std::uint32_t channels = 1);

// How many cells the basis function at each coefficient position covers: size x size
// values, the whole grid for the average at [0], (2 size / s)^2 for a detail of the active
// s x s block (max(row, column) in [s/2, s)). Throws opal::Error unless size is a power of
// two. The bake ranks transfer coefficients by it (what a light coefficient grows with).
std::vector<float> haarSupportCells(std::uint32_t size);

}  // namespace opal
