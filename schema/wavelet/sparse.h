// Sparse wavelet coefficient vectors and matrices, and the selection rules of the two
// compression steps (keep the n largest; keep a fraction of the energy).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace opal {

struct SparseVector {
    std::vector<std::uint32_t> indices;  // ascending
    std::vector<float> values;

    std::size_t size() const { return indices.size(); }
};

// The n coefficients of largest magnitude (ties broken by lower index, so the choice is
// deterministic), indices ascending. Exact zeros are never kept, so fewer than n come
// back when the vector has fewer nonzeros. Throws opal::Error on a non-finite value or a
// vector longer than 2^32 - 1. Expected O(dense.size()) time (selection, not a sort).
SparseVector keepLargest(std::span<const float> dense, std::size_t n);

// The fewest coefficients whose energy sum_i c_i^2 g_i reaches `fraction` of the total,
// where g_i = normsSquared[i] (all 1 when empty: an orthonormal basis). Indices ascending.
// Coefficients are ranked by energy, ties broken by lower index (deterministic).
// fraction 1 keeps every coefficient of nonzero energy, fraction 0 keeps none. Throws
// opal::Error when fraction is outside [0, 1], normsSquared is neither empty nor
// dense.size() long, or a value or norm is not finite (or a norm is negative).
// Expected O(dense.size()) time.
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

// Append `row` as the next row of `matrix` (rows + 1). Throws opal::Error when an index
// is not below matrix.cols. An empty matrix (no rowOffsets yet) is started first.
void appendRow(SparseMatrix& matrix, const SparseVector& row);

// Throw opal::Error, message prefixed with `context` (e.g. "candle.opal: chunk TRN0"),
// unless the matrix is consistent: rows + 1 offsets starting at 0, non-decreasing, ending
// at nonZeros(); as many columns as values; columns strictly ascending within each row
// and below cols; every value finite.
void validate(const SparseMatrix& matrix, std::string_view context);

// y = A x for `channels` interleaved channels per entry: x holds cols * channels values,
// y rows * channels (overwritten). Parallel over rows when the matrix is large. Throws
// opal::Error on a size mismatch. The matrix is trusted (validate() it when read).
void multiply(const SparseMatrix& matrix, std::span<const float> x, std::span<float> y,
              std::uint32_t channels = 3);

}  // namespace opal
