#include "delegate/relight/transfer_product.h"

#include "delegate/relight/float4.h"
#include "schema/error.h"

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


// Row r of one matrix against x: sum over its entries of value x[column], lanes 4 L.
// Two accumulators halve the add dependency chain.
template <typename Index, std::size_t C, std::size_t L = (C + 3) / 4>
void productRow(const std::uint64_t* offsets, const Index* column, const std::uint16_t* half, float scale,
                std::uint32_t r, const float* x, float* y) {
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

#if OPAL_TRANSFER_PRODUCT_AVX2
// The same row on AVX2 + FMA + F16C, chosen at run time (TransferProduct::Kernel): eight
// values converted by one vcvtph2ps, each entry one broadcast and one fused multiply-add
// per 8 lanes, where the portable row spends most of its instructions on the integer
// conversion and separate multiplies and adds (transfer_product.h has the timings).
template <std::size_t W>
__attribute__((target("avx2,fma,f16c"))) inline void accumulate(const float* v, const float* xp, __m256& acc8,
                                                              __m128& acc4) {
    if constexpr (W >= 8) acc8 = _mm256_fmadd_ps(_mm256_broadcast_ss(v), _mm256_loadu_ps(xp), acc8);
    if constexpr (W != 8) acc4 = _mm_fmadd_ps(_mm_broadcast_ss(v), _mm_loadu_ps(xp + W - 4), acc4);
}

template <typename Index, std::size_t C>
__attribute__((target("avx2,fma,f16c"))) void productRowAvx2(const std::uint64_t* offsets, const Index* column,
                                                              const std::uint16_t* half, float scale, std::uint32_t r,
                                                              const float* x, float* y) {
    constexpr std::size_t W = (C + 3) / 4 * 4;  // 4, 8 or 12 lanes: ymm for 0-7, xmm for the last 4
    __m256 even8 = _mm256_setzero_ps(), odd8 = _mm256_setzero_ps();
    __m128 even4 = _mm_setzero_ps(), odd4 = _mm_setzero_ps();
    std::uint64_t e = offsets[r];
    const std::uint64_t stop = offsets[r + 1];
    alignas(32) float v[8];
    for (; e + 8 <= stop; e += 8) {
        _mm256_store_ps(v, _mm256_cvtph_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(half + e))));
        for (std::size_t j = 0; j < 8; j += 2) {
            accumulate<W>(v + j, x + std::size_t(column[e + j]) * W, even8, even4);
            accumulate<W>(v + j + 1, x + std::size_t(column[e + j + 1]) * W, odd8, odd4);
        }
    }
    for (; e < stop; ++e) {
        v[0] = _cvtsh_ss(half[e]);
        accumulate<W>(v, x + std::size_t(column[e]) * W, even8, even4);
    }
    alignas(32) float sum[W];
    if constexpr (W >= 8) _mm256_store_ps(sum, _mm256_mul_ps(_mm256_add_ps(even8, odd8), _mm256_set1_ps(scale)));
    if constexpr (W != 8) _mm_storeu_ps(sum + W - 4, _mm_mul_ps(_mm_add_ps(even4, odd4), _mm_set1_ps(scale)));
    std::copy_n(sum, C, y);
}

// Six channels (two moments x RGB, padded to 8 lanes) on AVX-512: two entries per fused
// multiply-add, each entry's 8 lanes of x in one half of a 16-lane register and its value
// broadcast to that half by one permute. A row's tail (fewer than 8 entries) runs as the
// AVX2 row does (transfer_product.h has the timings).
template <typename Index>
__attribute__((target("avx512f,avx512vl,avx512dq,avx2,fma,f16c"))) inline __m512 twoEntries(
    __m512 v, __m512i pair, const float* x, const Index* column, __m512 acc) {
    const __m256 first = _mm256_loadu_ps(x + std::size_t(column[0]) * 8);
    const __m256 second = _mm256_loadu_ps(x + std::size_t(column[1]) * 8);
    const __m512 xs = _mm512_insertf32x8(_mm512_insertf32x8(_mm512_setzero_ps(), first, 0), second, 1);
    return _mm512_fmadd_ps(_mm512_mask_permutexvar_ps(v, __mmask16(0xffff), pair, v), xs, acc);  // masked: GCC 12 warns on the unmasked form
}

template <typename Index>
__attribute__((target("avx512f,avx512vl,avx512dq,avx2,fma,f16c"))) void productRowAvx512Lanes8(
    const std::uint64_t* offsets, const Index* column, const std::uint16_t* half, float scale, std::uint32_t r,
    const float* x, float* y, std::size_t C) {
    constexpr std::size_t W = 8;
    const __m512i pair[4] = {_mm512_set_epi32(1, 1, 1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0),
                             _mm512_set_epi32(3, 3, 3, 3, 3, 3, 3, 3, 2, 2, 2, 2, 2, 2, 2, 2),
                             _mm512_set_epi32(5, 5, 5, 5, 5, 5, 5, 5, 4, 4, 4, 4, 4, 4, 4, 4),
                             _mm512_set_epi32(7, 7, 7, 7, 7, 7, 7, 7, 6, 6, 6, 6, 6, 6, 6, 6)};
    __m512 even = _mm512_setzero_ps(), odd = _mm512_setzero_ps();
    std::uint64_t e = offsets[r];
    const std::uint64_t stop = offsets[r + 1];
    for (; e + 8 <= stop; e += 8) {
        const __m512 v =
            _mm512_insertf32x8(_mm512_setzero_ps(), _mm256_cvtph_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(half + e))), 0);
        even = twoEntries(v, pair[0], x, column + e, even);
        odd = twoEntries(v, pair[1], x, column + e + 2, odd);
        even = twoEntries(v, pair[2], x, column + e + 4, even);
        odd = twoEntries(v, pair[3], x, column + e + 6, odd);
    }
    alignas(64) float halves[16];  // the two entries' halves, summed (GCC 12's extract intrinsics warn)
    _mm512_store_ps(halves, _mm512_add_ps(even, odd));
    __m256 tail = _mm256_add_ps(_mm256_load_ps(halves), _mm256_load_ps(halves + 8));
    for (; e < stop; ++e)
        tail = _mm256_fmadd_ps(_mm256_set1_ps(_cvtsh_ss(half[e])), _mm256_loadu_ps(x + std::size_t(column[e]) * W), tail);
    alignas(32) float sum[W];
    _mm256_store_ps(sum, _mm256_mul_ps(tail, _mm256_set1_ps(scale)));
    std::copy_n(sum, C, y);
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

TransferProduct::TransferProduct(const CompressedTransfer& transfer, std::size_t samples, Kernel kernel)
    : samples_(samples), kernel_(kernel) {
    if (kernel == Kernel::Best)
        kernel_ = cpuHasAvx512Kernel() ? Kernel::Avx512 : cpuHasAvx2Kernel() ? Kernel::Avx2 : Kernel::Portable;
    if (!kernelAvailable(kernel_))
        throw Error(std::string("transfer product: this CPU lacks ") +
                    (kernel_ == Kernel::Avx512 ? "AVX-512 (F, VL, DQ), " : "") + "AVX2, FMA or F16C");
    if (samples > std::numeric_limits<std::uint32_t>::max()) throw Error("transfer product: too many samples");
    const bool narrow = samples <= 65536;
    for (std::size_t k = 0; k < transfer.perBasis.size(); ++k) {
        const SparseMatrix& m = transfer.perBasis[k];
        const std::string what = "transfer product: matrix " + std::to_string(k) + ": ";
        if (m.rows != samples || m.cols != samples || m.rowOffsets.size() != samples + 1 ||
            m.rowOffsets.back() != m.values.size() || m.columns.size() != m.values.size())
            throw Error(what + "shape or offsets do not match " + std::to_string(samples) + " samples");
        Matrix out;
        const int e = halfScaleExponent(m.values);
        out.scale = std::ldexp(1.0f, e);
        out.rowOffsets.reserve(samples + 1);
        out.rowOffsets.push_back(0);
        for (std::uint32_t r = 0; r < m.rows; ++r) {
            for (std::uint64_t i = m.rowOffsets[r]; i < m.rowOffsets[r + 1]; ++i) {
                if (m.columns[i] >= samples) throw Error(what + "column index out of range");
                if (!std::isfinite(m.values[i])) throw Error(what + "a value is not finite");
                std::uint16_t half = 0;
                if (!toNormalHalf(m.values[i], e, half)) continue;  // zero or subnormal: dropped
                out.halves.push_back(half);
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
    if ((C != 3 && C != 6 && C != 9) || lanes != (C + 3) / 4 * 4)
        throw Error("transfer product: " + std::to_string(C) + " channels in " + std::to_string(lanes) +
                    " lanes (3, 6 or 9 channels, lanes rounded up to 4)");
    const std::size_t K = matrices_.size();
    for (std::size_t k = 0; k < K; ++k) {
        const Matrix& m = matrices_[k];
        const auto rows = [&](auto index, auto channels) {
            constexpr std::size_t Cs = decltype(channels)::value;
            using Index = std::remove_cv_t<std::remove_pointer_t<decltype(index)>>;
#if OPAL_TRANSFER_PRODUCT_AVX2
            if constexpr (Cs == 6) {
                if (kernel_ == Kernel::Avx512) {
                    for (std::uint32_t r = begin; r < end; ++r)
                        productRowAvx512Lanes8<Index>(m.rowOffsets.data(), index, m.halves.data(), m.scale, r, x,
                                                      y + (r * K + k) * Cs, Cs);
                    return;
                }
            }
            if (kernel_ != Kernel::Portable) {
                for (std::uint32_t r = begin; r < end; ++r)
                    productRowAvx2<Index, Cs>(m.rowOffsets.data(), index, m.halves.data(), m.scale, r, x,
                                              y + (r * K + k) * Cs);
                return;
            }
#endif
            for (std::uint32_t r = begin; r < end; ++r)
                productRow<Index, Cs>(m.rowOffsets.data(), index, m.halves.data(), m.scale, r, x, y + (r * K + k) * Cs);
        };
        const auto withIndex = [&](auto channels) {
            if (samples_ <= 65536)
                rows(m.columns16.data(), channels);
            else
                rows(m.columns32.data(), channels);
        };
        if (C == 3) withIndex(std::integral_constant<std::size_t, 3>{});
        if (C == 6) withIndex(std::integral_constant<std::size_t, 6>{});
        if (C == 9) withIndex(std::integral_constant<std::size_t, 9>{});
    }
}

std::size_t TransferProduct::memoryBytes() const {
    std::size_t bytes = matrices_.capacity() * sizeof(Matrix);
    for (const Matrix& m : matrices_)
        bytes += m.rowOffsets.capacity() * sizeof(std::uint64_t) + m.columns16.capacity() * sizeof(std::uint16_t) +
                 m.columns32.capacity() * sizeof(std::uint32_t) + m.halves.capacity() * sizeof(std::uint16_t);
    return bytes;
}

}  // namespace opal
