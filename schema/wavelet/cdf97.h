// 2D CDF 9/7 biorthogonal wavelet (Cohen-Daubechies-Feauveau, the JPEG 2000 irreversible
// filter) by lifting with symmetric extension, in place on a size x size grid, size a
// power of two. Used for the spatial (output) dimension of the transfer (step 2, "w1").
#pragma once

#include "schema/wavelet/chart_layout.h"

#include <span>
#include <vector>

namespace opal {

template <typename T> void cdf97Forward2D(std::span<T> grid, std::uint32_t size);
template <typename T> void cdf97Inverse2D(std::span<T> grid, std::uint32_t size);

template <typename T> void cdf97ForwardCharts(std::span<T> data, const ChartLayout& layout);
template <typename T> void cdf97InverseCharts(std::span<T> data, const ChartLayout& layout);

// The 9/7 basis is not orthonormal: a coefficient c at grid index i contributes
// c^2 * synthesisNormSquared[i] to the reconstructed signal's energy (up to the small
// cross terms of a biorthogonal basis). size*size values, one per coefficient position.
std::vector<float> cdf97SynthesisNormsSquared(std::uint32_t size);

}  // namespace opal
