// The wavelet domain of an asset: M charts, each a 2^n x 2^n grid of surface samples
// (docs/ARCHITECTURE.md#wavelet-domain). Sample i lives in chart i / (size*size), at row
// (i % (size*size)) / size and column i % size: samples are stored in grid order, so the
// layout is implicit.
#pragma once

#include <cstddef>
#include <cstdint>

namespace opal {

struct ChartLayout {
    std::uint32_t charts = 0;    // M
    std::uint32_t log2Size = 0;  // n

    std::uint32_t size() const { return 1u << log2Size; }
    std::size_t cellsPerChart() const { return std::size_t(size()) * size(); }
    std::size_t cells() const { return cellsPerChart() * charts; }
};

}  // namespace opal
