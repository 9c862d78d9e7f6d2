// How the sidecar stores the compressed transfer's values (SIDECAR.md, chunk TRNS).
//
// Step 2 of the bake keeps the coefficient c at row p (a 9/7 coefficient of the output)
// and column j (a Haar coefficient of the light) of T_k when its weighted amplitude
//     u = c sqrt(g_p a_j) sqrt(lambda_k / lambda_1)
// reaches a threshold tau (g_p: squared norm of the 9/7 synthesis function at p; a_j:
// cells covered by Haar function j; lambda_k: the PCA eigenvalue of b_k; see
// bake/transfer_builder.h). Values are stored on a grid uniform in that same amplitude:
//     c = q step_k / (sqrt(g_p) sqrt(a_j)),   q an integer,
// with step_k = tau / (4 sqrt(lambda_k / lambda_1)) chosen by the bake. Rounding moves a
// kept coefficient by at most an eighth of the smallest kept amplitude, which adds ~2% to
// the transfer error step 2 already makes (measured: 0.92% -> 0.935%), while q is a small
// integer for most coefficients, which zstd stores in about a byte (two thirds of the
// bytes of half floats). A step of 0 means the values are stored exactly (float32): a
// lossless bake stays lossless.
//
// g_p and a_j depend only on the position inside a chart, so the grid is known from the
// chart layout alone; reader and writer compute it the same way.
#pragma once

#include "schema/wavelet/chart_layout.h"
#include "schema/wavelet/sparse.h"

#include <cstdint>
#include <span>
#include <vector>

namespace opal {

class TransferValueGrid {
public:
    // Throws opal::Error for a layout whose charts are not a power-of-two size.
    explicit TransferValueGrid(const ChartLayout& layout);

    // sqrt(g_p) sqrt(a_j): the amplitude weight of entry (p, j).
    double weight(std::uint32_t p, std::uint32_t j) const {
        return rowScale_[p % cellsPerChart_] * columnScale_[j % cellsPerChart_];
    }
    // q = round(c weight / step), step > 0.
    std::int64_t quantize(float c, double step, std::uint32_t p, std::uint32_t j) const;
    // c = q step / weight, as a float.
    float value(std::int64_t q, double step, std::uint32_t p, std::uint32_t j) const;
    // quantize for every entry of m, in m's entry order; step > 0.
    std::vector<std::int64_t> quantize(const SparseMatrix& m, double step) const;
    // value for every entry of m (its shape; its values are not read) from q in entry order.
    std::vector<float> values(const SparseMatrix& m, std::span<const std::int64_t> q, double step) const;
    // Every value of m replaced by value(quantize(.)); nothing changes for step 0.
    // Idempotent. m's shape must match the layout (unchecked beyond p, j < cells).
    void round(SparseMatrix& m, double step) const;

private:
    std::size_t cellsPerChart_ = 1;
    std::vector<double> rowScale_;     // sqrt(g) per chart position
    std::vector<double> columnScale_;  // sqrt(a) per chart position
};

}  // namespace opal
