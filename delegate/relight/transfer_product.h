// The relighting engine's working copy of the compressed transfer
// (docs/ARCHITECTURE.md#relighting), laid out for the one operation a light edit waits for:
// y_k = (w1 T_k w0^-1) wE for every k.
//
// That product streams every entry of the K sparse matrices once per light edit (58
// million entries on the 65,536-sample bunny) and gathers wE at each entry's column. With
// the asset's floats it was bound by memory traffic; so entries are stored in 4 bytes
// instead of 8:
//   column  16 bits when the asset has at most 65,536 samples, else 32;
//   value   scaled binary16 (scaled_half.h), e per matrix: 11 significant bits, entries
//           below 2^-28 of the matrix's largest dropped.
// after which the instructions per entry decide, and an AVX2 + FMA + F16C row (chosen at
// run time) does in one broadcast and one fused multiply-add per 8 lanes what the portable
// row needs a dozen operations for. Measured on that bunny (2 cores, medians of noisy
// runs), a point-light move's products: asset floats 47 ms, compact portable 41 ms,
// compact AVX2 33 ms. With the shipped step-2 energy (84 million entries), AVX2 34.5-35.2
// ms and AVX-512 29.5-31.2 ms (alternating runs of `opal-bench relight --case light`): for
// six channels, the common case, two entries share one 16-lane fused multiply-add.
#pragma once

#include "delegate/relight/scaled_half.h"
#include "schema/asset/translucent_asset.h"

#include <cstdint>
#include <span>
#include <vector>

namespace opal {

class TransferProduct {
public:
    // The row kernel: Best picks Avx512 where the CPU also has AVX-512 F, VL and DQ, else
    // Avx2 where it has AVX2, FMA and F16C (checked at run time; the build stays baseline
    // x86-64), else Portable. Avx512 differs from Avx2 only for 6 channels. All give the
    // same sums up to float rounding order.
    enum class Kernel { Best, Portable, Avx2, Avx512 };
    static bool kernelAvailable(Kernel kernel);

    // Throws opal::Error unless every matrix is samples x samples with consistent CSR, or
    // when the kernel asked for is not available.
    TransferProduct(const CompressedTransfer& transfer, std::size_t samples, Kernel kernel = Kernel::Best);

    Kernel kernel() const { return kernel_; }
    // Bytes of the compact matrices (what the delegate reports per mesh).
    std::size_t memoryBytes() const;

    std::size_t matrices() const { return matrices_.size(); }
    std::size_t samples() const { return samples_; }
    std::uint64_t nonZeros() const;

    // y[(r * K + k) * C + c] = sum_e T_k[r, j_e] x[j_e * lanes + c] for every row r in
    // [begin, end), every k and c < C; C is 3, 6 or 9 (1 to 3 moments x RGB) and lanes, the
    // stride of x (padded with zeros), is C rounded up to a multiple of 4.
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
    Kernel kernel_ = Kernel::Portable;
    std::vector<Matrix> matrices_;
};

}  // namespace opal
