#include "delegate/relight/transfer_product.h"

#include "delegate/relight/float4.h"
#include "delegate/relight/prefetch.h"
#include "schema/asset/sidecar_checks.h"
#include "schema/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define OPAL_TRANSFER_PRODUCT_AVX2 1
#include "delegate/relight/cpu_avx2.h"

#include <immintrin.h>
#else
#define OPAL_TRANSFER_PRODUCT_AVX2 0
#endif

namespace opal {

namespace {

constexpr std::size_t kGroup = 8;  // columns per group; every row is whole groups

// How far ahead of the group being summed the vector kernels prefetch a pair's values and
// columns (prefetch.h), in columns (1.5 KB of values). The hardware's prefetchers alone left the AVX-512
// row at about 5.6 cycles a column on the 65,536-sample bunny, with its reads of wE all
// from L1 no faster (a temporary build), so it waited on the streamed arrays. Products per
// point-light move there (opal-bench relight, medians, alternating runs, 2026-11-28): none
// 38.1-39.2 ms; 128 columns 33.6; 256 30.7; 384 29.1; 512 29.9-30.1; 768 31.8; 1024 32.5;
// 2048 32.7.
constexpr std::size_t kPrefetchColumns = 384;

// The next groups' values (two binary16 a column) and columns, kPrefetchColumns ahead of
// column e.
template <typename Index>
inline void prefetchGroups(const std::uint16_t* half, const Index* column, std::uint64_t e) {
    prefetchAhead(half + 2 * e, kPrefetchColumns * 2 * sizeof(std::uint16_t));
    prefetchAhead(column + e, kPrefetchColumns * sizeof(Index));
}

// One pair's rows as the kernels read them, and where their sums go:
// y + (r K + k) C for the first matrix, C further on for the second (when there is one).
template <typename Index>
struct PairRows {
    const std::uint64_t* offsets;
    const Index* column;
    const std::uint16_t* half;  // two per column
    const float* scale;         // two
    const std::uint32_t* rowAt; // stored row q is row rowAt[q] of the matrices (null: q)
    float* y;
    std::size_t K, k;
    bool second;

    float* first(std::uint32_t q, std::size_t C) const {
        return y + (std::size_t(rowAt ? rowAt[q] : q) * K + k) * C;
    }
};

// The scaled sum of two accumulator chains, C channels of it, to y.
template <std::size_t C, std::size_t L>
void storeSum(const Float4 (&acc)[2][L], float scale, float* y) {
    float sum[4 * L];
    for (std::size_t l = 0; l < L; ++l) {
        const Float4 total = (acc[0][l] + acc[1][l]) * scale;
        std::memcpy(sum + 4 * l, &total, sizeof total);
    }
    std::copy_n(sum, C, y);
}

// Rows [begin, end) of a pair against x, lanes 4 L, two chains per matrix (even and odd
// columns) to halve the add dependency.
template <typename Index, std::size_t C, std::size_t L = (C + 3) / 4>
void pairRowsPortable(const PairRows<Index>& p, const float* x, std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t r = begin; r < end; ++r) {
        Float4 a[2][L] = {}, b[2][L] = {};
        for (std::uint64_t e = p.offsets[r]; e < p.offsets[r + 1]; e += 2)
            for (std::size_t h = 0; h < 2; ++h) {
                const float va = storedHalfToFloat(p.half[2 * (e + h)]), vb = storedHalfToFloat(p.half[2 * (e + h) + 1]);
                const float* xp = x + std::size_t(p.column[e + h]) * 4 * L;
                for (std::size_t l = 0; l < L; ++l) {
                    const Float4 xv = load4(xp + 4 * l);
                    a[h][l] += va * xv;
                    b[h][l] += vb * xv;
                }
            }
        storeSum<C>(a, p.scale[0], p.first(r, C));
        if (p.second) storeSum<C>(b, p.scale[1], p.first(r, C) + C);
    }
}

#if OPAL_TRANSFER_PRODUCT_AVX2
// The same rows on AVX2 + FMA + F16C, chosen at run time (TransferProduct::Kernel): sixteen
// values converted by two vcvtph2ps, each column's x loaded once for both matrices, each
// value one broadcast and one fused multiply-add per 8 lanes, where the portable row spends
// most of its instructions on the integer conversion and separate multiplies and adds.
struct Avx2Chains {  // one pair's sums: lanes 0-7 and the last 4, each matrix
    __m256 a8, b8;
    __m128 a4, b4;
};

__attribute__((target("avx2,fma,f16c"))) inline Avx2Chains zeroChains() {
    return {_mm256_setzero_ps(), _mm256_setzero_ps(), _mm_setzero_ps(), _mm_setzero_ps()};
}

template <std::size_t W>
__attribute__((target("avx2,fma,f16c"))) inline void accumulatePair(const float* v, const float* xp,
                                                                  Avx2Chains& acc) {
    if constexpr (W >= 8) {
        const __m256 xv = _mm256_loadu_ps(xp);
        acc.a8 = _mm256_fmadd_ps(_mm256_broadcast_ss(v), xv, acc.a8);
        acc.b8 = _mm256_fmadd_ps(_mm256_broadcast_ss(v + 1), xv, acc.b8);
    }
    if constexpr (W != 8) {
        const __m128 xv = _mm_loadu_ps(xp + W - 4);
        acc.a4 = _mm_fmadd_ps(_mm_broadcast_ss(v), xv, acc.a4);
        acc.b4 = _mm_fmadd_ps(_mm_broadcast_ss(v + 1), xv, acc.b4);
    }
}

template <std::size_t C, std::size_t W>
__attribute__((target("avx2,fma,f16c"))) inline void storeAvx2(__m256 sum8, __m128 sum4, float scale, float* y) {
    alignas(32) float sum[W];
    if constexpr (W >= 8) _mm256_store_ps(sum, _mm256_mul_ps(sum8, _mm256_set1_ps(scale)));
    if constexpr (W != 8) _mm_storeu_ps(sum + W - 4, _mm_mul_ps(sum4, _mm_set1_ps(scale)));
    std::copy_n(sum, C, y);
}

template <typename Index, std::size_t C>
__attribute__((target("avx2,fma,f16c"))) void pairRowsAvx2(const PairRows<Index>& p, const float* x,
                                                            std::uint32_t begin, std::uint32_t end) {
    constexpr std::size_t W = (C + 3) / 4 * 4;  // 4, 8 or 12 lanes: ymm for 0-7, xmm for the last 4
    alignas(32) float v[2 * kGroup];
    for (std::uint32_t r = begin; r < end; ++r) {
        Avx2Chains even = zeroChains(), odd = zeroChains();
        for (std::uint64_t e = p.offsets[r]; e < p.offsets[r + 1]; e += kGroup) {
            prefetchGroups(p.half, p.column, e);
            const auto* h = reinterpret_cast<const __m128i*>(p.half + 2 * e);
            _mm256_store_ps(v, _mm256_cvtph_ps(_mm_loadu_si128(h)));
            _mm256_store_ps(v + 8, _mm256_cvtph_ps(_mm_loadu_si128(h + 1)));
            for (std::size_t j = 0; j < kGroup; j += 2) {
                accumulatePair<W>(v + 2 * j, x + std::size_t(p.column[e + j]) * W, even);
                accumulatePair<W>(v + 2 * j + 2, x + std::size_t(p.column[e + j + 1]) * W, odd);
            }
        }
        float* y = p.first(r, C);
        storeAvx2<C, W>(_mm256_add_ps(even.a8, odd.a8), _mm_add_ps(even.a4, odd.a4), p.scale[0], y);
        if (p.second) storeAvx2<C, W>(_mm256_add_ps(even.b8, odd.b8), _mm_add_ps(even.b4, odd.b4), p.scale[1], y + C);
    }
}

// Six channels (two moments x RGB, padded to 8 lanes) on AVX-512: a column's 8 lanes of x
// in both halves of a 16-lane register, times its two values, each spread over its half by
// one permute: one fused multiply-add per column for both matrices. Eight chains, one per
// column of a group, so the adds do not wait on each other.
template <typename Index>
__attribute__((target("avx512f,avx512vl,avx512dq,avx2,fma,f16c"))) void pairRowsAvx512Lanes8(
    const PairRows<Index>& p, const float* x, std::uint32_t begin, std::uint32_t end) {
    constexpr std::size_t C = 6, W = 8;
    constexpr __mmask16 kAll = 0xffff;  // masked forms throughout: GCC 12 warns on the unmasked ones
    __m512i spread[kGroup];  // column j's values sit at lanes 2j and 2j + 1 of the converted group
    for (int j = 0; j < int(kGroup); ++j)
        spread[j] = _mm512_set_epi32(2 * j + 1, 2 * j + 1, 2 * j + 1, 2 * j + 1, 2 * j + 1, 2 * j + 1, 2 * j + 1,
                                     2 * j + 1, 2 * j, 2 * j, 2 * j, 2 * j, 2 * j, 2 * j, 2 * j, 2 * j);
    const __m512 scale = _mm512_insertf32x8(_mm512_set1_ps(p.scale[0]), _mm256_set1_ps(p.scale[1]), 1);
    const __m512i pack = _mm512_set_epi32(0, 0, 0, 0, 13, 12, 11, 10, 9, 8, 5, 4, 3, 2, 1, 0);
    for (std::uint32_t r = begin; r < end; ++r) {
        __m512 acc[kGroup];
        for (__m512& a : acc) a = _mm512_setzero_ps();
        for (std::uint64_t e = p.offsets[r]; e < p.offsets[r + 1]; e += kGroup) {
            prefetchGroups(p.half, p.column, e);
            const __m512 v = _mm512_maskz_cvtph_ps(kAll, _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p.half + 2 * e)));
            for (std::size_t j = 0; j < kGroup; ++j) {
                const __m512 xs = _mm512_maskz_broadcast_f32x8(kAll, _mm256_loadu_ps(x + std::size_t(p.column[e + j]) * W));
                acc[j] = _mm512_fmadd_ps(_mm512_maskz_permutexvar_ps(kAll, spread[j], v), xs, acc[j]);
            }
        }
        const __m512 sum = _mm512_add_ps(_mm512_add_ps(_mm512_add_ps(acc[0], acc[1]), _mm512_add_ps(acc[2], acc[3])),
                                         _mm512_add_ps(_mm512_add_ps(acc[4], acc[5]), _mm512_add_ps(acc[6], acc[7])));
        // Lanes 0-5 and 8-13 side by side, stored straight to y by one masked store: a copy
        // through memory here (a 64-byte store read back in parts) cost a fifth of the kernel.
        const __m512 packed = _mm512_maskz_permutexvar_ps(kAll, pack, _mm512_mul_ps(sum, scale));
        _mm512_mask_storeu_ps(p.first(r, C), p.second ? __mmask16(0x0fff) : __mmask16(0x003f), packed);
    }
}

bool cpuHasAvx2Kernel() { return cpuHasAvx2FmaF16c(); }
bool cpuHasAvx512Kernel() {
    return cpuHasAvx2FmaF16c() && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
           __builtin_cpu_supports("avx512dq");
}
#else
bool cpuHasAvx2Kernel() { return false; }
bool cpuHasAvx512Kernel() { return false; }
#endif

void checkSlots(const std::vector<std::uint32_t>& slots, std::size_t samples) {
    if (slots.empty()) return;
    if (slots.size() != samples)
        throw Error("transfer product: " + std::to_string(slots.size()) + " input slots for " + std::to_string(samples) +
                    " samples");
    std::vector<bool> taken(samples, false);
    for (std::uint32_t s : slots) {
        if (s >= samples || taken[s]) throw Error("transfer product: the input slots are not a permutation");
        taken[s] = true;
    }
}

// A samples x samples CSR matrix with offsets from 0 that never fall, columns strictly
// ascending within a row and below samples, and finite values (the sidecar reader's checks).
void checkMatrix(const SparseMatrix& m, std::size_t k, std::size_t samples) {
    const std::string what = "matrix " + std::to_string(k);
    if (m.rows != samples || m.cols != samples || m.columns.size() != m.values.size())
        throw Error("transfer product: " + what + " is " + std::to_string(m.rows) + " x " + std::to_string(m.cols) +
                    " with " + std::to_string(m.columns.size()) + " columns for " + std::to_string(m.values.size()) +
                    " values; expected " + std::to_string(samples) + " x " + std::to_string(samples));
    sidecar::checkOffsets(std::span<const std::uint64_t>(m.rowOffsets), samples, m.values.size(), "transfer product",
                          what + " offsets");
    sidecar::checkIndices(std::span<const std::uint64_t>(m.rowOffsets), std::span<const std::uint32_t>(m.columns),
                          samples, true, "transfer product", what + " columns");
    sidecar::checkFinite(m.values, "transfer product", what + " values");
}

}  // namespace

bool TransferProduct::kernelAvailable(Kernel kernel) {
    switch (kernel) {
        case Kernel::Best:
        case Kernel::Portable: return true;
        case Kernel::Avx2: return cpuHasAvx2Kernel();
        case Kernel::Avx512: return cpuHasAvx512Kernel();
    }
    return false;
}

TransferProduct::TransferProduct(const CompressedTransfer& transfer, std::size_t samples, Kernel kernel,
                                 std::vector<std::uint32_t> slots)
    : samples_(samples), K_(transfer.perBasis.size()), kernel_(kernel), slots_(std::move(slots)) {
    if (kernel == Kernel::Best)
        kernel_ = cpuHasAvx512Kernel() ? Kernel::Avx512 : cpuHasAvx2Kernel() ? Kernel::Avx2 : Kernel::Portable;
    if (!kernelAvailable(kernel_))
        throw Error(std::string("transfer product: this CPU lacks ") +
                    (kernel_ == Kernel::Avx512 ? "AVX-512 (F, VL, DQ), " : "") + "AVX2, FMA or F16C");
    if (samples > std::numeric_limits<std::uint32_t>::max()) throw Error("transfer product: too many samples");
    checkSlots(slots_, samples);
    if (!slots_.empty()) {
        rowAt_.resize(samples);
        for (std::uint32_t j = 0; j < samples; ++j) rowAt_[slots_[j]] = j;
    }
    tbb::parallel_for(std::size_t(0), K_, [&](std::size_t k) { checkMatrix(transfer.perBasis[k], k, samples); });
    pairs_.resize((K_ + 1) / 2);
    tbb::parallel_for(std::size_t(0), pairs_.size(), [&](std::size_t g) { pairs_[g] = makePair(transfer, 2 * g); });
}

namespace {

constexpr std::uint32_t kRowsPerPiece = 2048;  // a pair is built in pieces of rows, in parallel

}  // namespace

// Stored rows [begin, end) of the pair from matrix `first` on: the union of the two
// matrices' columns in input-slot order, padded to whole groups with zero values at the
// row's last column (so padding reads nothing a row does not already read). Each entry is
// sorted as one key, slot << 32 | its binary16 at bit 16 h (h: which matrix).
TransferProduct::PairPiece TransferProduct::makePairPiece(const CompressedTransfer& transfer, std::size_t first,
                                                          const int* exponent, std::uint32_t begin,
                                                          std::uint32_t end) const {
    const std::size_t count = std::min<std::size_t>(2, K_ - first);
    PairPiece piece;
    std::vector<std::uint64_t> keys;
    for (std::uint32_t q = begin; q < end; ++q) {
        const std::uint32_t r = rowAt_.empty() ? q : rowAt_[q];
        keys.clear();
        for (std::size_t h = 0; h < count; ++h) {
            const SparseMatrix& m = transfer.perBasis[first + h];
            for (std::uint64_t i = m.rowOffsets[r]; i < m.rowOffsets[r + 1]; ++i) {  // checked (checkMatrix)
                std::uint16_t bits = 0;
                if (!toNormalHalf(m.values[i], exponent[h], bits)) continue;  // zero or subnormal: dropped
                const std::uint64_t slot = slots_.empty() ? m.columns[i] : slots_[m.columns[i]];
                keys.push_back(slot << 32 | std::uint64_t(bits) << (16 * h));
            }
        }
        std::sort(keys.begin(), keys.end());
        const std::size_t rowStart = piece.slots.size();
        for (std::size_t i = 0; i < keys.size(); ++i) {
            const std::uint32_t slot = std::uint32_t(keys[i] >> 32);
            const std::uint16_t a = std::uint16_t(keys[i]), b = std::uint16_t(keys[i] >> 16);
            if (i > 0 && slot == piece.slots.back()) {  // the other matrix's value of the same column
                piece.halves[piece.halves.size() - 2] |= a;
                piece.halves.back() |= b;
                continue;
            }
            piece.slots.push_back(slot);
            piece.halves.insert(piece.halves.end(), {a, b});
        }
        while ((piece.slots.size() - rowStart) % kGroup != 0) {
            piece.slots.push_back(piece.slots.back());
            piece.halves.insert(piece.halves.end(), 2, std::uint16_t(0));
        }
        piece.lengths.push_back(std::uint32_t(piece.slots.size() - rowStart));
    }
    return piece;
}

// Matrices first and first + 1 (or first alone, the last of an odd K) as one pair, built in
// pieces of rows in parallel and joined in order.
TransferProduct::Pair TransferProduct::makePair(const CompressedTransfer& transfer, std::size_t first) const {
    Pair pair;
    int exponent[2] = {0, 0};
    for (std::size_t h = 0; h < std::min<std::size_t>(2, K_ - first); ++h) {
        exponent[h] = halfScaleExponent(transfer.perBasis[first + h].values);
        pair.scale[h] = std::ldexp(1.0f, exponent[h]);
    }
    std::vector<PairPiece> pieces((samples_ + kRowsPerPiece - 1) / kRowsPerPiece);
    tbb::parallel_for(std::size_t(0), pieces.size(), [&](std::size_t b) {
        const std::uint32_t begin = std::uint32_t(b * kRowsPerPiece);
        pieces[b] = makePairPiece(transfer, first, exponent, begin,
                                  std::uint32_t(std::min<std::size_t>(samples_, begin + kRowsPerPiece)));
    });
    std::size_t columns = 0;
    for (const PairPiece& piece : pieces) columns += piece.slots.size();
    pair.columns = CompactIndices(samples_);
    pair.columns.reserve(columns);
    pair.halves.reserve(2 * columns);
    pair.rowOffsets.reserve(samples_ + 1);
    pair.rowOffsets.push_back(0);
    for (const PairPiece& piece : pieces) {
        pair.columns.append(piece.slots);
        pair.halves.insert(pair.halves.end(), piece.halves.begin(), piece.halves.end());
        for (std::uint32_t length : piece.lengths) pair.rowOffsets.push_back(pair.rowOffsets.back() + length);
    }
    return pair;
}

std::uint64_t TransferProduct::nonZeros() const {
    std::uint64_t n = 0;
    for (const Pair& p : pairs_) n += std::uint64_t(std::count_if(p.halves.begin(), p.halves.end(), [](std::uint16_t h) { return h != 0; }));
    return n;
}

float TransferProduct::value(std::size_t k, std::uint32_t row, std::uint32_t column) const {
    if (k >= K_ || row >= samples_ || column >= samples_) throw Error("transfer product: entry out of range");
    const Pair& p = pairs_[k / 2];
    const std::uint32_t slot = slots_.empty() ? column : slots_[column];
    const std::uint32_t q = slots_.empty() ? row : slots_[row];
    for (std::uint64_t i = p.rowOffsets[q]; i < p.rowOffsets[q + 1]; ++i)
        if (p.columns[i] == slot) return storedHalfToFloat(p.halves[2 * i + k % 2]) * p.scale[k % 2];
    return 0.0f;
}

void TransferProduct::arrangeInput(std::span<const float> wE, std::size_t lanes, std::span<float> x) const {
    if (wE.size() != samples_ * lanes || x.size() != wE.size())
        throw Error("transfer product: input of " + std::to_string(wE.size()) + " and " + std::to_string(x.size()) +
                    " values for " + std::to_string(samples_) + " samples x " + std::to_string(lanes) + " lanes");
    if (slots_.empty()) {
        std::copy(wE.begin(), wE.end(), x.begin());
        return;
    }
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples_, 4096), [&](const tbb::blocked_range<std::size_t>& js) {
        for (std::size_t j = js.begin(); j != js.end(); ++j)
            std::copy_n(wE.data() + j * lanes, lanes, x.data() + std::size_t(slots_[j]) * lanes);
    });
}

void TransferProduct::multiplyRows(const float* x, std::size_t lanes, float* y, std::size_t C, std::uint32_t begin,
                                   std::uint32_t end) const {
    if ((C != 3 && C != 6 && C != 9) || lanes != (C + 3) / 4 * 4)
        throw Error("transfer product: " + std::to_string(C) + " channels in " + std::to_string(lanes) +
                    " lanes (3, 6 or 9 channels, lanes rounded up to 4)");
    if (begin > end || end > samples_)
        throw Error("transfer product: rows [" + std::to_string(begin) + ", " + std::to_string(end) + ") of " +
                    std::to_string(samples_));
    for (std::size_t g = 0; g < pairs_.size(); ++g) {
        const Pair& pair = pairs_[g];
        const auto rows = [&](const auto* index, auto channels) {
            constexpr std::size_t Cs = decltype(channels)::value;
            using Index = std::remove_cv_t<std::remove_pointer_t<decltype(index)>>;
            const PairRows<Index> p{pair.rowOffsets.data(), index, pair.halves.data(), pair.scale,
                                    rowAt_.empty() ? nullptr : rowAt_.data(), y, K_, 2 * g, 2 * g + 1 < K_};
#if OPAL_TRANSFER_PRODUCT_AVX2
            if constexpr (Cs == 6) {
                if (kernel_ == Kernel::Avx512) return pairRowsAvx512Lanes8<Index>(p, x, begin, end);
            }
            if (kernel_ != Kernel::Portable) return pairRowsAvx2<Index, Cs>(p, x, begin, end);
#endif
            pairRowsPortable<Index, Cs>(p, x, begin, end);
        };
        const auto withIndex = [&](auto channels) {
            pair.columns.withData([&](const auto* index) { rows(index, channels); });
        };
        if (C == 3) withIndex(std::integral_constant<std::size_t, 3>{});
        if (C == 6) withIndex(std::integral_constant<std::size_t, 6>{});
        if (C == 9) withIndex(std::integral_constant<std::size_t, 9>{});
    }
}

std::size_t TransferProduct::memoryBytes() const {
    std::size_t bytes = pairs_.capacity() * sizeof(Pair) + (slots_.capacity() + rowAt_.capacity()) * sizeof(std::uint32_t);
    for (const Pair& p : pairs_)
        bytes += p.rowOffsets.capacity() * sizeof(std::uint64_t) + p.columns.memoryBytes() +
                 p.halves.capacity() * sizeof(std::uint16_t);
    return bytes;
}

}  // namespace opal
