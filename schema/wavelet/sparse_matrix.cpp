// Compressed-sparse-row helpers: building, validating (for the sidecar reader) and the
// runtime product y_k = T_k wE with RGB interleaved (docs/ARCHITECTURE.md#relighting).
#include "schema/wavelet/sparse.h"

#include "schema/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace opal {

namespace {

[[noreturn]] void fail(std::string_view context, const std::string& what) {
    throw Error(std::string(context) + ": sparse matrix " + what);
}

void validateOffsets(const SparseMatrix& m, std::string_view context) {
    if (m.rowOffsets.size() != std::size_t(m.rows) + 1)
        fail(context,
             "has " + std::to_string(m.rowOffsets.size()) +
                 " row offsets, expected rows + 1 = " + std::to_string(std::size_t(m.rows) + 1));
    if (m.rowOffsets.front() != 0)
        fail(context, "row offsets start at " + std::to_string(m.rowOffsets.front()) + ", not 0");
    for (std::uint32_t r = 0; r < m.rows; ++r)
        if (m.rowOffsets[r + 1] < m.rowOffsets[r])
            fail(context, "row " + std::to_string(r) + " ends before it starts");
    if (m.rowOffsets.back() != m.values.size())
        fail(context, "row offsets end at " + std::to_string(m.rowOffsets.back()) +
                          " but there are " + std::to_string(m.values.size()) + " values");
    if (m.columns.size() != m.values.size())
        fail(context, "has " + std::to_string(m.columns.size()) + " column indices for " +
                          std::to_string(m.values.size()) + " values");
}

void validateRow(const SparseMatrix& m, std::uint32_t r, std::string_view context) {
    for (std::uint64_t k = m.rowOffsets[r]; k < m.rowOffsets[r + 1]; ++k) {
        const std::string where = "row " + std::to_string(r) + " entry " + std::to_string(k);
        if (m.columns[k] >= m.cols)
            fail(context, where + ": column " + std::to_string(m.columns[k]) +
                              " out of range (cols = " + std::to_string(m.cols) + ")");
        if (k > m.rowOffsets[r] && m.columns[k] <= m.columns[k - 1])
            fail(context, where + ": columns not strictly ascending");
        if (!std::isfinite(m.values[k])) fail(context, where + ": value is not finite");
    }
}

// y[r] = sum_k A[r, col_k] x[col_k] for rows [begin, end), C channels at compile time.
template <std::uint32_t C>
void multiplyRows(const SparseMatrix& m, const float* x, float* y, std::uint32_t begin,
                  std::uint32_t end) {
    for (std::uint32_t r = begin; r < end; ++r) {
        float sum[C] = {};
        for (std::uint64_t k = m.rowOffsets[r]; k < m.rowOffsets[r + 1]; ++k) {
            const float a = m.values[k];
            const float* xc = x + std::size_t(m.columns[k]) * C;
            for (std::uint32_t c = 0; c < C; ++c) sum[c] += a * xc[c];
        }
        for (std::uint32_t c = 0; c < C; ++c) y[std::size_t(r) * C + c] = sum[c];
    }
}

// The same for any channel count, accumulating in y.
void multiplyRows(const SparseMatrix& m, const float* x, float* y, std::uint32_t channels,
                  std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t r = begin; r < end; ++r) {
        float* yr = y + std::size_t(r) * channels;
        std::fill(yr, yr + channels, 0.0f);
        for (std::uint64_t k = m.rowOffsets[r]; k < m.rowOffsets[r + 1]; ++k) {
            const float* xc = x + std::size_t(m.columns[k]) * channels;
            for (std::uint32_t c = 0; c < channels; ++c) yr[c] += m.values[k] * xc[c];
        }
    }
}

void multiplyRange(const SparseMatrix& m, const float* x, float* y, std::uint32_t channels,
                   std::uint32_t begin, std::uint32_t end) {
    switch (channels) {
        case 1:
            multiplyRows<1>(m, x, y, begin, end);
            break;
        case 3:
            multiplyRows<3>(m, x, y, begin, end);
            break;
        default:
            multiplyRows(m, x, y, channels, begin, end);
            break;
    }
}

}  // namespace

void appendRow(SparseMatrix& matrix, const SparseVector& row) {
    for (std::uint32_t column : row.indices)
        if (column >= matrix.cols)
            throw Error("appendRow: column " + std::to_string(column) +
                        " out of range (cols = " + std::to_string(matrix.cols) + ")");
    if (matrix.rowOffsets.empty()) matrix.rowOffsets.push_back(0);
    matrix.columns.insert(matrix.columns.end(), row.indices.begin(), row.indices.end());
    matrix.values.insert(matrix.values.end(), row.values.begin(), row.values.end());
    matrix.rowOffsets.push_back(matrix.values.size());
    ++matrix.rows;
}

void validate(const SparseMatrix& matrix, std::string_view context) {
    validateOffsets(matrix, context);
    for (std::uint32_t r = 0; r < matrix.rows; ++r) validateRow(matrix, r, context);
}

void multiply(const SparseMatrix& matrix, std::span<const float> x, std::span<float> y,
              std::uint32_t channels) {
    if (channels == 0) throw Error("multiply: channels must be at least 1");
    if (x.size() != std::size_t(matrix.cols) * channels ||
        y.size() != std::size_t(matrix.rows) * channels)
        throw Error("multiply: " + std::to_string(matrix.rows) + " x " +
                    std::to_string(matrix.cols) + " matrix with " + std::to_string(channels) +
                    " channels needs x of " + std::to_string(std::size_t(matrix.cols) * channels) +
                    " and y of " + std::to_string(std::size_t(matrix.rows) * channels) +
                    " values, got " + std::to_string(x.size()) + " and " +
                    std::to_string(y.size()));
    constexpr std::size_t kParallelNonZeros = 1 << 16;
    if (matrix.nonZeros() < kParallelNonZeros) {
        multiplyRange(matrix, x.data(), y.data(), channels, 0, matrix.rows);
        return;
    }
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, matrix.rows, 256),
                      [&](const tbb::blocked_range<std::uint32_t>& rows) {
                          multiplyRange(matrix, x.data(), y.data(), channels, rows.begin(),
                                        rows.end());
                      });
}

}  // namespace opal
