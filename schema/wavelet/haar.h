// 2D orthonormal Haar wavelet, nonstandard decomposition (Stollnitz, DeRose and Salesin),
// in place on a row-major size x size grid, size a power of two. Used for the light
// dimension of the transfer (step 1, "w0") and for environment maps and visibility.
#pragma once

#include "schema/wavelet/chart_layout.h"

#include <span>

namespace opal {

template <typename T> void haarForward2D(std::span<T> grid, std::uint32_t size);
template <typename T> void haarInverse2D(std::span<T> grid, std::uint32_t size);

// The same on every chart of a layout (data.size() == layout.cells()).
template <typename T> void haarForwardCharts(std::span<T> data, const ChartLayout& layout);
template <typename T> void haarInverseCharts(std::span<T> data, const ChartLayout& layout);

}  // namespace opal
