// The relighting engine's working copy of the compressed transfer
// (docs/ARCHITECTURE.md#relighting), laid out for the one operation a light edit waits for:
// y_k = (w1 T_k w0^-1) wE for every k.
//
// That product streams every entry of the K sparse matrices once per light edit (84
// million entries on the 65,536-sample bunny) and gathers wE at each entry's column. It is
// bound by the instructions and loads per entry, not by memory traffic, so the layout is
// chosen to do fewer of them:
//   pairs     matrices 2g and 2g + 1 share one column list, the union of theirs (a value
//             slot holds 0 where one of the two has no entry): one load of wE serves both.
//             On that bunny the pairs hold 54 million columns for 84 million entries.
//   rows      padded with zero values to whole groups of 8 columns, so no kernel has a tail,
//             and stored in the locality order of haar_locality_order.h, so that rows read
//             one after the other gather nearby columns.
//   columns   16 bits when the asset has at most 65,536 samples, else 32, numbering wE in
//             that locality order too (arrangeInput puts wE there).
//   values    scaled binary16 (scaled_half.h), e per matrix: 11 significant bits, entries
//             below 2^-28 of the matrix's largest dropped.
// Kernels, chosen at run time: portable; AVX2 + FMA + F16C (one broadcast and one fused
// multiply-add per value and 8 lanes); AVX-512 for six channels (two moments x RGB, the
// common case: a pair's two values times one column's 8 lanes in one 16-lane fused
// multiply-add). Timings on that bunny: delegate/DELEGATE.md.
#pragma once

#include "delegate/relight/compact_indices.h"
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

    // slots: empty (wE read and rows stored in their own order) or slots[j], the place of
    // coefficient j in the product's input and of row j in its storage, a permutation of
    // [0, samples) (haarLocalitySlots).
    // Throws opal::Error unless every matrix is samples x samples with consistent CSR and
    // finite values, when slots is not such a permutation, or when the kernel asked for is
    // not available.
    TransferProduct(const CompressedTransfer& transfer, std::size_t samples, Kernel kernel = Kernel::Best,
                    std::vector<std::uint32_t> slots = {});

    Kernel kernel() const { return kernel_; }
    // Bytes of the compact matrices and the orders (what the delegate reports per mesh; a
    // light edit streams the matrices).
    std::size_t memoryBytes() const;

    std::size_t matrices() const { return K_; }
    std::size_t samples() const { return samples_; }
    // Stored values that are not zero (entries of the asset's matrices that were kept).
    std::uint64_t nonZeros() const;

    // x[slots[j] * lanes + c] = wE[j * lanes + c]: the input multiplyRows reads.
    void arrangeInput(std::span<const float> wE, std::size_t lanes, std::span<float> x) const;

    // y[(r * K + k) * C + c] = sum_j T_k[r, j] wE[j * lanes + c] for every k, c < C and
    // every row r stored at [begin, end), with x = arrangeInput(wE); C is 3, 6 or 9 (1 to 3
    // moments x RGB) and lanes, the stride of x (padded with zeros), is C rounded up to a
    // multiple of 4. No allocation; callers split [0, samples) across threads.
    void multiplyRows(const float* x, std::size_t lanes, float* y, std::size_t C, std::uint32_t begin,
                      std::uint32_t end) const;

    // T_k[row, column] as the product uses it; 0 when not stored (for tests).
    float value(std::size_t k, std::uint32_t row, std::uint32_t column) const;

private:
    struct Pair {  // matrices 2g and 2g + 1 (the second all zero when K is odd and 2g + 1 = K)
        std::vector<std::uint64_t> rowOffsets;  // into columns; every row a multiple of 8 long
        CompactIndices columns;                 // input slots
        std::vector<std::uint16_t> halves;      // two per column: binary16 of v 2^-e, or 0
        float scale[2] = {1.0f, 1.0f};          // 2^e of each matrix
    };
    struct PairPiece {  // stored rows of one pair, built apart and joined in order
        std::vector<std::uint32_t> slots;    // columns
        std::vector<std::uint16_t> halves;   // two per column
        std::vector<std::uint32_t> lengths;  // per row, whole groups
    };
    Pair makePair(const CompressedTransfer& transfer, std::size_t first) const;
    PairPiece makePairPiece(const CompressedTransfer& transfer, std::size_t first, const int* exponent,
                            std::uint32_t begin, std::uint32_t end) const;

    std::size_t samples_ = 0, K_ = 0;
    Kernel kernel_ = Kernel::Portable;
    std::vector<std::uint32_t> slots_;  // empty: identity
    std::vector<std::uint32_t> rowAt_;  // the inverse of slots_: the row stored at q
    std::vector<Pair> pairs_;
};

}  // namespace opal
