#include "delegate/relight/haar_locality_order.h"

#include "schema/error.h"

#include <algorithm>
#include <bit>
#include <numeric>

namespace opal {

namespace {

// Interleave the bits of (i, j): i's in the odd places, j's in the even ones.
std::uint64_t morton(std::uint32_t i, std::uint32_t j) {
    std::uint64_t m = 0;
    for (unsigned b = 0; b < 32; ++b) m |= (std::uint64_t(i >> b & 1u) << (2 * b + 1)) | (std::uint64_t(j >> b & 1u) << (2 * b));
    return m;
}

// Within one chart of side S: the scaling coefficient (0, 0) is level 0; a detail
// coefficient with max(row, column) in [h, 2h) belongs to level log2(h) + 1, band
// 2 (row >= h) + (column >= h), place (row mod h, column mod h).
std::uint64_t localityKey(std::uint32_t row, std::uint32_t column) {
    const std::uint32_t largest = std::max(row, column);
    if (largest == 0) return 0;
    const std::uint32_t level = std::uint32_t(std::bit_width(largest));
    const std::uint32_t h = 1u << (level - 1);
    const std::uint32_t band = 2u * (row >= h) + (column >= h);
    return (std::uint64_t(level) << 58) | (morton(row % h, column % h) << 2) | band;
}

}  // namespace

std::vector<std::uint32_t> haarLocalitySlots(const ChartLayout& layout) {
    // The key holds a level below 64 and a place's 2 x 15 bits: charts up to 2^16 a side,
    // beyond anything a sidecar holds (sidecar_checks.h).
    if (layout.log2Size > 16)
        throw Error("Haar locality order: charts of 2^" + std::to_string(layout.log2Size) + " cells a side are too large");
    const std::uint32_t S = layout.size();
    const std::size_t perChart = layout.cellsPerChart();
    std::vector<std::uint32_t> chartOrder(perChart);  // chartOrder[q]: the Mallat index at slot q
    std::iota(chartOrder.begin(), chartOrder.end(), 0u);
    std::vector<std::uint64_t> key(perChart);
    for (std::uint32_t p = 0; p < perChart; ++p) key[p] = localityKey(p / S, p % S);
    std::sort(chartOrder.begin(), chartOrder.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
    std::vector<std::uint32_t> slots(layout.cells());
    for (std::size_t chart = 0; chart < layout.charts; ++chart)
        for (std::size_t q = 0; q < perChart; ++q)
            slots[chart * perChart + chartOrder[q]] = std::uint32_t(chart * perChart + q);
    return slots;
}

}  // namespace opal
