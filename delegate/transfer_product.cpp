#include "delegate/transfer_product.h"

#include "schema/error.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

namespace opal {

namespace {

// Four floats in one SSE register (GCC/Clang vector extension): the compilers keep these
// in registers, where plain float arrays of the same loops were vectorized poorly.
using Float4 = float __attribute__((vector_size(16)));

inline Float4 load4(const float* p) {
    Float4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

constexpr int kHalfTopExponent = 15;   // the largest |v| 2^-e lands in (2^14, 2^15]
constexpr float kSmallestNormalHalf = 6.103515625e-05f;  // 2^-14

// e with max |v| 2^-e in (2^14, 2^15]; 0 for an all-zero matrix.
int scaleExponent(const std::vector<float>& values) {
    float largest = 0.0f;
    for (float v : values) largest = std::max(largest, std::abs(v));
    if (largest == 0.0f) return 0;
    int exponent = 0;
    const float mantissa = std::frexp(largest, &exponent);
    return (mantissa == 0.5f ? exponent - 1 : exponent) - kHalfTopExponent;
}

// Row r of one matrix against x: sum over its entries of value x[column], lanes 4 L.
// Two accumulators halve the add dependency chain.
template <typename Index, std::size_t L>
void productRow(const std::uint64_t* offsets, const Index* column, const std::uint16_t* half, float scale,
                std::uint32_t r, const float* x, float* y, std::size_t C) {
    Float4 even[L] = {}, odd[L] = {};
    std::uint64_t e = offsets[r];
    const std::uint64_t stop = offsets[r + 1];
    for (; e + 2 <= stop; e += 2) {
        const float v0 = normalHalfToFloat(half[e]), v1 = normalHalfToFloat(half[e + 1]);
        const float* x0 = x + std::size_t(column[e]) * 4 * L;
        const float* x1 = x + std::size_t(column[e + 1]) * 4 * L;
        for (std::size_t l = 0; l < L; ++l) {
            even[l] += v0 * load4(x0 + 4 * l);
            odd[l] += v1 * load4(x1 + 4 * l);
        }
    }
    if (e < stop) {
        const float v0 = normalHalfToFloat(half[e]);
        const float* x0 = x + std::size_t(column[e]) * 4 * L;
        for (std::size_t l = 0; l < L; ++l) even[l] += v0 * load4(x0 + 4 * l);
    }
    float sum[4 * L];
    for (std::size_t l = 0; l < L; ++l) {
        const Float4 total = (even[l] + odd[l]) * scale;
        std::memcpy(sum + 4 * l, &total, sizeof total);
    }
    std::copy_n(sum, C, y);
}

}  // namespace

TransferProduct::TransferProduct(const CompressedTransfer& transfer, std::size_t samples) : samples_(samples) {
    if (samples > std::numeric_limits<std::uint32_t>::max()) throw Error("transfer product: too many samples");
    const bool narrow = samples <= 65536;
    for (std::size_t k = 0; k < transfer.perBasis.size(); ++k) {
        const SparseMatrix& m = transfer.perBasis[k];
        const std::string what = "transfer product: matrix " + std::to_string(k) + ": ";
        if (m.rows != samples || m.cols != samples || m.rowOffsets.size() != samples + 1 ||
            m.rowOffsets.back() != m.values.size() || m.columns.size() != m.values.size())
            throw Error(what + "shape or offsets do not match " + std::to_string(samples) + " samples");
        Matrix out;
        const int e = scaleExponent(m.values);
        out.scale = std::ldexp(1.0f, e);
        out.rowOffsets.reserve(samples + 1);
        out.rowOffsets.push_back(0);
        for (std::uint32_t r = 0; r < m.rows; ++r) {
            for (std::uint64_t i = m.rowOffsets[r]; i < m.rowOffsets[r + 1]; ++i) {
                if (m.columns[i] >= samples) throw Error(what + "column index out of range");
                const float scaled = std::ldexp(m.values[i], -e);
                if (!std::isfinite(scaled)) throw Error(what + "a value is not finite");
                const Imath::half h(scaled);
                if (!(std::abs(float(h)) >= kSmallestNormalHalf)) continue;  // zero or subnormal: dropped
                out.halves.push_back(h.bits());
                if (narrow)
                    out.columns16.push_back(std::uint16_t(m.columns[i]));
                else
                    out.columns32.push_back(m.columns[i]);
            }
            out.rowOffsets.push_back(out.halves.size());
        }
        matrices_.push_back(std::move(out));
    }
}

std::uint64_t TransferProduct::nonZeros() const {
    std::uint64_t n = 0;
    for (const Matrix& m : matrices_) n += m.halves.size();
    return n;
}

float TransferProduct::value(std::size_t k, std::uint64_t e) const {
    return normalHalfToFloat(matrices_[k].halves[e]) * matrices_[k].scale;
}

std::uint32_t TransferProduct::column(std::size_t k, std::uint64_t e) const {
    return samples_ <= 65536 ? matrices_[k].columns16[e] : matrices_[k].columns32[e];
}

void TransferProduct::multiplyRows(const float* x, std::size_t lanes, float* y, std::size_t C, std::uint32_t begin,
                                   std::uint32_t end) const {
    const std::size_t K = matrices_.size();
    for (std::size_t k = 0; k < K; ++k) {
        const Matrix& m = matrices_[k];
        const auto rows = [&](auto index, auto lanesOf4) {
            constexpr std::size_t L = decltype(lanesOf4)::value;
            for (std::uint32_t r = begin; r < end; ++r)
                productRow<std::remove_cv_t<std::remove_pointer_t<decltype(index)>>, L>(
                    m.rowOffsets.data(), index, m.halves.data(), m.scale, r, x, y + (r * K + k) * C, C);
        };
        const auto withIndex = [&](auto lanesOf4) {
            if (samples_ <= 65536)
                rows(m.columns16.data(), lanesOf4);
            else
                rows(m.columns32.data(), lanesOf4);
        };
        switch (lanes) {
            case 4: withIndex(std::integral_constant<std::size_t, 1>{}); break;
            case 8: withIndex(std::integral_constant<std::size_t, 2>{}); break;
            case 12: withIndex(std::integral_constant<std::size_t, 3>{}); break;
            default: throw Error("transfer product: " + std::to_string(lanes) + " lanes (4, 8 or 12)");
        }
    }
}

}  // namespace opal
