#include "schema/wavelet/haar.h"

#include "schema/wavelet/nonstandard.h"
#include "schema/wavelet/scratch.h"

#include <algorithm>
#include <bit>
#include <numbers>
#include <utility>

namespace opal {

namespace {

// The orthonormal Haar step (Stollnitz et al. 1995, section 2, normalized):
// (a, b) -> ((a + b) / sqrt 2, (a - b) / sqrt 2). It is its own inverse.
//
// A level of the nonstandard decomposition (one step along every row of the active s x s
// block, then one along every column; nonstandard.h) only ever combines the four cells of
// a 2 x 2 block, so both steps are done at once per block, reading the block from a
// compact copy of the active low-low quadrant and writing the three details straight to
// their Mallat-layout places in the grid: one pass per level instead of four. Each
// output is computed by exactly the operations of the separate row and column steps, so
// the results are the same bits.
template <typename T>
constexpr T kInvSqrt2 = T(1) / std::numbers::sqrt2_v<T>;

// Values per cell: a compile-time 1 (the bake's scalar rows: the loops vectorize) or a
// run-time count (interleaved channels: the innermost loop runs over them).
struct OneChannel {
    static constexpr std::size_t count = 1;
};
struct Channels {
    std::size_t count;
};

// Where the active level's quadrants live in the chart (row stride `size` cells): for
// block row r, the row-high details (r, half + c), the column-high ones (half + r, c) and
// the diagonal ones (half + r, half + c).
template <typename T>
struct DetailRows {
    T* rowHigh;
    T* columnHigh;
    T* diagonal;
};

template <typename T, typename C>
DetailRows<T> detailRows(T* grid, std::size_t size, std::size_t half, std::size_t r, C ch) {
    T* columnHigh = grid + (half + r) * size * ch.count;
    return {grid + (r * size + half) * ch.count, columnHigh, columnHigh + half * ch.count};
}

// One analysis level: `in` is the s x s low-low block (compact, row stride s), the new
// low-low quadrant goes to `lowLow` (compact, stride s / 2), details into `grid`.
template <typename T, typename C>
void analyzeLevel(const T* __restrict in, std::size_t s, T* __restrict lowLow, T* __restrict grid,
                  std::size_t size, C ch) {
    const T k = kInvSqrt2<T>;
    const std::size_t half = s / 2, n = ch.count;
    for (std::size_t r = 0; r < half; ++r) {
        const T* __restrict top = in + 2 * r * s * n;
        const T* __restrict bottom = top + s * n;
        T* __restrict ll = lowLow + r * half * n;
        const DetailRows<T> d = detailRows(grid, size, half, r, ch);
        for (std::size_t c = 0; c < half; ++c)
            for (std::size_t v = 0; v < n; ++v) {
                const std::size_t left = 2 * c * n + v, right = left + n, out = c * n + v;
                const T l0 = (top[left] + top[right]) * k, h0 = (top[left] - top[right]) * k;
                const T l1 = (bottom[left] + bottom[right]) * k, h1 = (bottom[left] - bottom[right]) * k;
                ll[out] = (l0 + l1) * k;
                d.columnHigh[out] = (l0 - l1) * k;
                d.rowHigh[out] = (h0 + h1) * k;
                d.diagonal[out] = (h0 - h1) * k;
            }
    }
}

// The inverse level: lowLow (compact, stride s / 2) and the details in `grid` give the
// s x s block in `out` (compact, stride s). Columns first, then rows, as the inverse of
// analyzeLevel must be; same operations as those two steps done separately.
template <typename T, typename C>
void synthesizeLevel(const T* __restrict lowLow, const T* __restrict grid, std::size_t size, std::size_t s,
                     T* __restrict out, C ch) {
    const T k = kInvSqrt2<T>;
    const std::size_t half = s / 2, n = ch.count;
    for (std::size_t r = 0; r < half; ++r) {
        const T* __restrict ll = lowLow + r * half * n;
        const DetailRows<const T> d = detailRows(grid, size, half, r, ch);
        T* __restrict top = out + 2 * r * s * n;
        T* __restrict bottom = top + s * n;
        for (std::size_t c = 0; c < half; ++c)
            for (std::size_t v = 0; v < n; ++v) {
                const std::size_t at = c * n + v, left = 2 * c * n + v, right = left + n;
                const T l0 = (ll[at] + d.columnHigh[at]) * k, l1 = (ll[at] - d.columnHigh[at]) * k;
                const T h0 = (d.rowHigh[at] + d.diagonal[at]) * k, h1 = (d.rowHigh[at] - d.diagonal[at]) * k;
                top[left] = (l0 + h0) * k;
                top[right] = (l0 - h0) * k;
                bottom[left] = (l1 + h1) * k;
                bottom[right] = (l1 - h1) * k;
            }
    }
}

// Levels s = size, size / 2, ..., 2, ping-ponging the low-low block between two scratch
// buffers; the final 1 x 1 average goes to the grid's first cell.
template <typename T, typename C>
void analyzeGrid(T* grid, std::size_t size, C ch) {
    if (size < 2) return;
    const std::size_t values = size * size * ch.count;
    std::span<T> scratch = wavelet_detail::threadScratch<T>(values + values / 4);
    T* in = scratch.data();
    T* lowLow = in + values;
    std::copy_n(grid, values, in);
    for (std::size_t s = size; s > 1; s /= 2) {
        analyzeLevel(in, s, lowLow, grid, size, ch);
        std::swap(in, lowLow);
    }
    std::copy_n(in, ch.count, grid);
}

// Levels s = 2, 4, ..., size; both buffers can hold a whole grid, so the last level's
// output (in either) is copied back in one go.
template <typename T, typename C>
void synthesizeGrid(T* grid, std::size_t size, C ch) {
    if (size < 2) return;
    const std::size_t values = size * size * ch.count;
    std::span<T> scratch = wavelet_detail::threadScratch<T>(2 * values);
    T* lowLow = scratch.data();
    T* out = lowLow + values;
    std::copy_n(grid, ch.count, lowLow);
    for (std::size_t s = 2; s <= size; s *= 2) {
        synthesizeLevel(lowLow, grid, size, s, out, ch);
        std::swap(lowLow, out);
    }
    std::copy_n(lowLow, values, grid);
}

template <typename T>
void analyze(T* grid, std::size_t size, std::uint32_t channels) {
    if (channels == 1) analyzeGrid(grid, size, OneChannel{});
    else analyzeGrid(grid, size, Channels{channels});
}

template <typename T>
void synthesize(T* grid, std::size_t size, std::uint32_t channels) {
    if (channels == 1) synthesizeGrid(grid, size, OneChannel{});
    else synthesizeGrid(grid, size, Channels{channels});
}

}  // namespace

template <typename T>
void haarForward2D(std::span<T> grid, std::uint32_t size, std::uint32_t channels) {
    wavelet_detail::checkGrid("haarForward2D", grid.size(), size, channels);
    analyze(grid.data(), size, channels);
}

template <typename T>
void haarInverse2D(std::span<T> grid, std::uint32_t size, std::uint32_t channels) {
    wavelet_detail::checkGrid("haarInverse2D", grid.size(), size, channels);
    synthesize(grid.data(), size, channels);
}

template <typename T>
void haarForwardCharts(std::span<T> data, const ChartLayout& layout, std::uint32_t channels) {
    wavelet_detail::checkCharts("haarForwardCharts", data.size(), layout, channels);
    const std::size_t perChart = layout.cellsPerChart() * channels;
    wavelet_detail::forEachChart(layout, channels, [&](std::uint32_t chart) {
        analyze(data.data() + chart * perChart, layout.size(), channels);
    });
}

template <typename T>
void haarInverseCharts(std::span<T> data, const ChartLayout& layout, std::uint32_t channels) {
    wavelet_detail::checkCharts("haarInverseCharts", data.size(), layout, channels);
    const std::size_t perChart = layout.cellsPerChart() * channels;
    wavelet_detail::forEachChart(layout, channels, [&](std::uint32_t chart) {
        synthesize(data.data() + chart * perChart, layout.size(), channels);
    });
}

std::vector<float> haarSupportCells(std::uint32_t size) {
    wavelet_detail::checkGrid("haarSupportCells", std::size_t(size) * size, size, 1);
    std::vector<float> cells(std::size_t(size) * size);
    for (std::uint32_t u = 0; u < size; ++u)
        for (std::uint32_t v = 0; v < size; ++v) {
            const std::uint32_t m = std::max(u, v);
            const double side = m == 0 ? double(size) : 2.0 * size / double(std::bit_floor(m) * 2);
            cells[std::size_t(u) * size + v] = float(side * side);
        }
    return cells;
}

template void haarForward2D<float>(std::span<float>, std::uint32_t, std::uint32_t);
template void haarInverse2D<float>(std::span<float>, std::uint32_t, std::uint32_t);
template void haarForwardCharts<float>(std::span<float>, const ChartLayout&, std::uint32_t);
template void haarInverseCharts<float>(std::span<float>, const ChartLayout&, std::uint32_t);
template void haarForward2D<double>(std::span<double>, std::uint32_t, std::uint32_t);
template void haarInverse2D<double>(std::span<double>, std::uint32_t, std::uint32_t);
template void haarForwardCharts<double>(std::span<double>, const ChartLayout&, std::uint32_t);
template void haarInverseCharts<double>(std::span<double>, const ChartLayout&, std::uint32_t);

}  // namespace opal
