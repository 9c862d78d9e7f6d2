#include "schema/asset/transfer_value_grid.h"

#include "schema/wavelet/cdf97.h"
#include "schema/wavelet/haar.h"

#include <cmath>

namespace opal {

TransferValueGrid::TransferValueGrid(const ChartLayout& layout) : cellsPerChart_(layout.cellsPerChart()) {
    for (float g : cdf97SynthesisNormsSquared(layout.size())) rowScale_.push_back(std::sqrt(double(g)));
    for (float a : haarSupportCells(layout.size())) columnScale_.push_back(std::sqrt(double(a)));
}

std::int64_t TransferValueGrid::quantize(float c, double step, std::uint32_t p, std::uint32_t j) const {
    return std::llround(double(c) * weight(p, j) / step);
}

float TransferValueGrid::value(std::int64_t q, double step, std::uint32_t p, std::uint32_t j) const {
    return float(double(q) * step / weight(p, j));
}

std::vector<std::int64_t> TransferValueGrid::quantize(const SparseMatrix& m, double step) const {
    std::vector<std::int64_t> q(m.values.size());
    for (std::uint32_t p = 0; p < m.rows; ++p)
        for (std::uint64_t e = m.rowOffsets[p]; e < m.rowOffsets[p + 1]; ++e)
            q[e] = quantize(m.values[e], step, p, m.columns[e]);
    return q;
}

std::vector<float> TransferValueGrid::values(const SparseMatrix& m, std::span<const std::int64_t> q,
                                             double step) const {
    std::vector<float> out(q.size());
    for (std::uint32_t p = 0; p < m.rows; ++p)
        for (std::uint64_t e = m.rowOffsets[p]; e < m.rowOffsets[p + 1]; ++e)
            out[e] = value(q[e], step, p, m.columns[e]);
    return out;
}

void TransferValueGrid::round(SparseMatrix& m, double step) const {
    if (step == 0.0) return;
    m.values = values(m, quantize(m, step), step);
}

}  // namespace opal
