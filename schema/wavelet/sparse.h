// Sparse wavelet coefficient vectors and matrices, and the selection rules of the two
// compression steps (keep the n largest; keep a fraction of the energy).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace opal {

struct SparseVector {
    std::vector<std::uint32_t> indices;  // ascending
    std::vector<float> values;

    std::size_t size() const { return indices.size(); }
};

// The n coefficients of largest magnitude (ties broken by lower index, so the choice is
// deterministic), indices ascending.
SparseVector keepLargest(std::span<const float> dense, std::size_t n);

// The fewest coefficients whose energy sum_i c_i^2 g_i reaches `fraction` of the total,
// where g_i = normsSquared[i] (all 1 when empty: an orthonormal basis). Indices ascending.
SparseVector keepEnergyFraction(std::span<const float> dense, double fraction,
                                std::span<const float> normsSquared = {});

// Compressed sparse rows, float values.
struct SparseMatrix {
    std::uint32_t rows = 0, cols = 0;
    std::vector<std::uint64_t> rowOffsets;  // rows + 1
    std::vector<std::uint32_t> columns;
    std::vector<float> values;

    std::size_t nonZeros() const { return values.size(); }
};

}  // namespace opal
