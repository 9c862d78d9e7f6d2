// The nonstandard 2D decomposition shared by the Haar and CDF 9/7 transforms (Stollnitz,
// DeRose and Salesin, "Wavelets for computer graphics: a primer, part 1", 1995, section
// 3): at each level one 1D step along every row of the active s x s block, then one
// along every column, then recurse on the low-low (top-left) s/2 x s/2 quadrant, down to
// a coarsest low-low block (1 x 1 for Haar). The result is the Mallat quadrant layout.
// Internal to schema/wavelet.
//
// A 1D step works on a deinterleaved buffer: `half` low blocks followed by `half` high
// blocks, each block `width` contiguous values. Along a row a block is one cell (width =
// channels); along the columns a block is a whole row segment (width = s * channels), so
// the column pass is a row-vector operation with unit stride, as fast as the row pass.
//   Step::analyze(T* lo, T* hi, std::size_t half, std::size_t width)
//   Step::synthesize(T* lo, T* hi, std::size_t half, std::size_t width)
#pragma once

#include "schema/wavelet/chart_layout.h"
#include "schema/wavelet/scratch.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string_view>

namespace opal::wavelet_detail {

// Throw opal::Error unless `size` is a power of two (at most 65536), channels is in
// [1, 65536] and the span holds size * size * channels values.
void checkGrid(std::string_view function, std::size_t values, std::uint32_t size,
               std::uint32_t channels);
void checkCharts(std::string_view function, std::size_t values, const ChartLayout& layout,
                 std::uint32_t channels);

// transformChart(c) for every chart c, in parallel (TBB) when the data is large enough
// to pay for the task overhead.
void forEachChart(const ChartLayout& layout, std::uint32_t channels,
                  const std::function<void(std::uint32_t chart)>& transformChart);

// A cell (a few channels) or a row segment. Cells are copied value by value: a memmove
// call per cell would cost more than the lifting itself.
template <typename T>
inline void copyBlock(const T* from, T* to, std::size_t width) {
    constexpr std::size_t kSmall = 4;
    if (width == 1) {
        *to = *from;
    } else if (width <= kSmall) {
        for (std::size_t k = 0; k < width; ++k) to[k] = from[k];
    } else {
        std::copy_n(from, width, to);
    }
}

// to = [blocks 0, 2, 4, ... | blocks 1, 3, 5, ...] of `from` (count blocks, `stride` apart).
template <typename T>
void deinterleave(const T* from, std::size_t stride, std::size_t width, std::size_t count, T* to) {
    const std::size_t half = count / 2;
    for (std::size_t l = 0; l < half; ++l) {
        copyBlock(from + 2 * l * stride, to + l * width, width);
        copyBlock(from + (2 * l + 1) * stride, to + (half + l) * width, width);
    }
}

// The inverse of deinterleave: block l of `from` goes to 2l, block half + l to 2l + 1.
template <typename T>
void interleave(const T* from, T* to, std::size_t stride, std::size_t width, std::size_t count) {
    const std::size_t half = count / 2;
    for (std::size_t l = 0; l < half; ++l) {
        copyBlock(from + l * width, to + 2 * l * stride, width);
        copyBlock(from + (half + l) * width, to + (2 * l + 1) * stride, width);
    }
}

// One analysis level on the active s x s block of a size x size grid.
template <typename Step, typename T>
void analyzeLevel(T* grid, std::size_t rowStride, std::size_t s, std::size_t channels,
                  std::span<T> scratch) {
    const std::size_t half = s / 2;
    for (std::size_t r = 0; r < s; ++r) {  // rows: blocks are cells
        T* row = grid + r * rowStride;
        deinterleave(row, channels, channels, s, scratch.data());
        Step::analyze(scratch.data(), scratch.data() + half * channels, half, channels);
        std::copy_n(scratch.data(), s * channels, row);
    }
    const std::size_t segment = s * channels;  // columns: blocks are row segments
    deinterleave(grid, rowStride, segment, s, scratch.data());
    Step::analyze(scratch.data(), scratch.data() + half * segment, half, segment);
    for (std::size_t r = 0; r < s; ++r)
        std::copy_n(scratch.data() + r * segment, segment, grid + r * rowStride);
}

// The inverse of analyzeLevel (columns first, then rows: the reverse order).
template <typename Step, typename T>
void synthesizeLevel(T* grid, std::size_t rowStride, std::size_t s, std::size_t channels,
                     std::span<T> scratch) {
    const std::size_t half = s / 2;
    const std::size_t segment = s * channels;
    for (std::size_t r = 0; r < s; ++r)
        std::copy_n(grid + r * rowStride, segment, scratch.data() + r * segment);
    Step::synthesize(scratch.data(), scratch.data() + half * segment, half, segment);
    interleave(scratch.data(), grid, rowStride, segment, s);
    for (std::size_t r = 0; r < s; ++r) {
        T* row = grid + r * rowStride;
        std::copy_n(row, segment, scratch.data());
        Step::synthesize(scratch.data(), scratch.data() + half * channels, half, channels);
        interleave(scratch.data(), row, channels, channels, s);
    }
}

// Full decomposition, levels s = size, size/2, ..., 2 * coarsest, leaving a coarsest x
// coarsest low-low block (coarsest a power of two). The caller has validated the grid.
template <typename Step, typename T>
void analyzeNonstandard(std::span<T> grid, std::uint32_t size, std::uint32_t channels,
                        std::uint32_t coarsest) {
    const std::size_t rowStride = std::size_t(size) * channels;
    std::span<T> scratch = threadScratch<T>(rowStride * size);
    for (std::size_t s = size; s > coarsest; s /= 2)
        analyzeLevel<Step>(grid.data(), rowStride, s, channels, scratch);
}

// Full reconstruction, levels s = 2 * coarsest, ..., size.
template <typename Step, typename T>
void synthesizeNonstandard(std::span<T> grid, std::uint32_t size, std::uint32_t channels,
                           std::uint32_t coarsest) {
    const std::size_t rowStride = std::size_t(size) * channels;
    std::span<T> scratch = threadScratch<T>(rowStride * size);
    for (std::size_t s = 2 * std::size_t(coarsest); s <= size; s *= 2)
        synthesizeLevel<Step>(grid.data(), rowStride, s, channels, scratch);
}

// analyzeNonstandard / synthesizeNonstandard on every chart of a layout (validated by
// the caller), in parallel over charts when worthwhile.
template <typename Step, typename T>
void analyzeCharts(std::span<T> data, const ChartLayout& layout, std::uint32_t channels,
                   std::uint32_t coarsest) {
    const std::size_t perChart = layout.cellsPerChart() * channels;
    forEachChart(layout, channels, [&](std::uint32_t chart) {
        analyzeNonstandard<Step>(data.subspan(chart * perChart, perChart), layout.size(), channels,
                                 coarsest);
    });
}

template <typename Step, typename T>
void synthesizeCharts(std::span<T> data, const ChartLayout& layout, std::uint32_t channels,
                      std::uint32_t coarsest) {
    const std::size_t perChart = layout.cellsPerChart() * channels;
    forEachChart(layout, channels, [&](std::uint32_t chart) {
        synthesizeNonstandard<Step>(data.subspan(chart * perChart, perChart), layout.size(),
                                    channels, coarsest);
    });
}

}  // namespace opal::wavelet_detail
