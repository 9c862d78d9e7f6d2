// 2D CDF 9/7 biorthogonal wavelet (Cohen-Daubechies-Feauveau, the JPEG 2000 irreversible
// filter) by lifting with symmetric extension, in place on a size x size grid, size a
// power of two. Used for the spatial (output) dimension of the transfer (step 2, "w1").
//
// Lifting factorization of Daubechies and Sweldens, "Factoring wavelet transforms into
// lifting steps" (1998), the (9-7) example of section 7 (the same alpha..delta as
// JPEG 2000 Part 1, Annex F).
// Band scaling: low *= zeta, high /= zeta with zeta = 1.149604398860241, so the analysis
// low-pass has DC gain sqrt(2) and the high-pass Nyquist gain sqrt(2): the taps are the
// "sqrt(2)-normalized" 9/7 pair, whose finest-level basis functions have squared norms
// 0.98 (low) and 1.04 (high), close to orthonormal. (JPEG 2000 uses K = 1.230174104914001
// instead, for gains 1 and 2; only the band scale differs.) Coarse and boundary functions
// stray further (squared norms 0.4 to 3), hence cdf97SynthesisNormsSquared.
//
// Boundaries use whole-sample symmetric extension (x[-k] = x[k], x[n-1+k] = x[n-1-k]),
// which lifting preserves exactly, so the transform is invertible for every even length,
// down to 2. The 2D transform is the nonstandard decomposition (one 1D step on rows, one
// on columns per level) with the same Mallat quadrant layout as haar.h.
//
// Levels stop at an 8 x 8 low-low band (cdf97CoarsestSize): one 2D level for sizes 2 to
// 16, then one more per doubling (3 levels for 64, 4 for 128). Below 8 samples the 9-tap
// filter wraps onto itself under symmetric extension and the coarse basis functions are
// far from orthogonal, so sum c_i^2 g_i (the energy rule of compression step 2) would
// overestimate the energy of a smooth signal up to 4-fold (measured on Gaussian bumps,
// 64 x 64, decomposed to 1 x 1); stopping at 8 x 8 keeps that estimate within ~6% and
// costs at most 64 coarse coefficients per chart.
//
// `channels` values per cell are stored interleaved and transformed independently. Bad
// input throws opal::Error. Explicitly instantiated for float and double.
#pragma once

#include "schema/wavelet/chart_layout.h"

#include <cstdint>
#include <span>
#include <vector>

namespace opal {

// The side of the low-low band the 2D transform stops at: min(8, size / 2), and 1 for a
// 1 x 1 grid (no level at all).
inline constexpr std::uint32_t kCdf97CoarsestSize = 8;
std::uint32_t cdf97CoarsestSize(std::uint32_t size);

// One 1D analysis level on an even-length signal: the result is [low half | high half],
// low[l] centered on x[2l], high[l] on x[2l+1]. The synthesis step is its exact inverse.
template <typename T>
void cdf97AnalysisStep1D(std::span<T> signal);
template <typename T>
void cdf97SynthesisStep1D(std::span<T> signal);

template <typename T>
void cdf97Forward2D(std::span<T> grid, std::uint32_t size, std::uint32_t channels = 1);
template <typename T>
void cdf97Inverse2D(std::span<T> grid, std::uint32_t size, std::uint32_t channels = 1);

// The same on every chart of a layout (data.size() == layout.cells() * channels), in
// parallel over charts when the data is large.
template <typename T>
void cdf97ForwardCharts(std::span<T> data, const ChartLayout& layout, std::uint32_t channels = 1);
template <typename T>
void cdf97InverseCharts(std::span<T> data, const ChartLayout& layout, std::uint32_t channels = 1);

// The 9/7 basis is not orthonormal: a coefficient c at grid index i contributes
// c^2 * synthesisNormSquared[i] to the reconstructed signal's energy, up to the cross
// terms of a biorthogonal basis (tests: within 2% for unstructured coefficients, 8% for a
// smooth bump). size*size values, one per coefficient position.
//
// Exact, boundary functions included: each 2D synthesis function of the nonstandard
// decomposition is the tensor product of two 1D functions of the same level, so its
// squared norm is the product of two 1D squared norms, each computed by synthesizing a
// 1D unit impulse (O(size^2) work in all).
std::vector<float> cdf97SynthesisNormsSquared(std::uint32_t size);

// The same tiled over every chart of a layout: layout.cells() values.
std::vector<float> cdf97SynthesisNormsSquared(const ChartLayout& layout);

}  // namespace opal
