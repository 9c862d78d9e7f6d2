// The relighting engine's working copy of the compressed transfer (DESIGN.md s.5), laid
// out for the one operation a light edit waits for: y_k = (w1 T_k w0^-1) wE for every k.
//
// That product streams every entry of the K sparse matrices once per light edit (58
// million entries on the 65,536-sample bunny) and gathers wE at each entry's column;
// measured, it is bound by memory traffic, not arithmetic. So entries are stored in 4
// bytes instead of the asset's 8:
//   column  16 bits when the asset has at most 65,536 samples, else 32;
//   value   IEEE binary16 of v 2^-e, e per matrix putting the largest |v| in (2^14, 2^15]
//           (as the sidecar's half planes), so every value keeps 11 significant bits
//           (relative rounding <= 2^-11). Entries whose half would be subnormal (below
//           2^-28 of the matrix's largest) are dropped: at most 2^-28 of a product each.
// Measured on that bunny, point-light move: products 47 ms with the asset's floats, 41 ms
// compact (2 cores).
#pragma once

#include "schema/asset/translucent_asset.h"

#include <cstdint>
#include <span>
#include <vector>

namespace opal {

class TransferProduct {
public:
    // Throws opal::Error unless every matrix is samples x samples with consistent CSR.
    TransferProduct(const CompressedTransfer& transfer, std::size_t samples);

    std::size_t matrices() const { return matrices_.size(); }
    std::size_t samples() const { return samples_; }
    std::uint64_t nonZeros() const;

    // y[(r * K + k) * C + c] = sum_e T_k[r, j_e] x[j_e * lanes + c] for every row r in
    // [begin, end), every k and c < C; lanes is 4, 8 or 12 (x padded with zeros), C <= lanes.
    // No allocation; callers split rows across threads.
    void multiplyRows(const float* x, std::size_t lanes, float* y, std::size_t C, std::uint32_t begin,
                      std::uint32_t end) const;

    // The value of entry e of matrix k as the product uses it (for tests).
    float value(std::size_t k, std::uint64_t e) const;
    std::uint32_t column(std::size_t k, std::uint64_t e) const;
    std::uint64_t rowBegin(std::size_t k, std::uint32_t r) const { return matrices_[k].rowOffsets[r]; }

private:
    struct Matrix {
        std::vector<std::uint64_t> rowOffsets;
        std::vector<std::uint16_t> columns16;  // when samples <= 65,536
        std::vector<std::uint32_t> columns32;  // otherwise
        std::vector<std::uint16_t> halves;     // binary16 of v 2^-e
        float scale = 1.0f;                    // 2^e
    };
    std::size_t samples_ = 0;
    std::vector<Matrix> matrices_;
};

// The float a normal binary16 bit pattern stands for (exponent field 1 to 30; what
// TransferProduct stores): re-bias the 5-bit exponent (15) to float's (127) and widen the
// 10-bit mantissa. Integer operations only, no table and no F16C.
inline float normalHalfToFloat(std::uint16_t h) {
    const std::uint32_t bits = (std::uint32_t(h & 0x8000u) << 16) | ((std::uint32_t(h & 0x7fffu) << 13) + (112u << 23));
    float f;
    __builtin_memcpy(&f, &bits, sizeof f);
    return f;
}

}  // namespace opal
