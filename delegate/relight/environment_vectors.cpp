#include "delegate/relight/environment_vectors.h"

#include "delegate/relight/dome_convolution.h"
#include "delegate/relight/float4.h"
#include "delegate/relight/prefetch.h"
#include "delegate/relight/scaled_half.h"
#include "schema/error.h"
#include "schema/scatter/fresnel_moments.h"
#include "schema/wavelet/haar.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <type_traits>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define OPAL_ENVIRONMENT_VECTORS_AVX2 1
#include "delegate/relight/cpu_avx2.h"

#include <immintrin.h>
#else
#define OPAL_ENVIRONMENT_VECTORS_AVX2 0
#endif

namespace opal {

namespace {

constexpr std::size_t kSamplesPerTask = 256;


std::string count(std::uint64_t n) { return std::to_string(n); }

struct Entry {
    std::uint32_t position;
    std::uint32_t m;
    float value;
};

#if OPAL_ENVIRONMENT_VECTORS_AVX2
// One sample on FMA + F16C (chosen at run time as TransferProduct chooses its kernel): the
// half conversions and fused multiply-adds that the portable loop spells out in integer
// and separate float operations. radiance: texels x 4.
template <typename Index, std::uint32_t M>
__attribute__((target("avx2,fma,f16c"))) void sampleAvx2(const Index* positions, const std::uint16_t* half,
                                                          std::uint64_t begin, std::uint64_t end,
                                                          const float* radiance, const float (&scales)[M], float* out) {
    __m128 even[M], odd[M];
    for (std::uint32_t m = 0; m < M; ++m) even[m] = odd[m] = _mm_setzero_ps();
    std::uint64_t e = begin;
    for (; e + 2 <= end; e += 2, half += 2 * M) {
        const __m128 l0 = _mm_loadu_ps(radiance + std::size_t(positions[e]) * 4);
        const __m128 l1 = _mm_loadu_ps(radiance + std::size_t(positions[e + 1]) * 4);
        for (std::uint32_t m = 0; m < M; ++m) {
            even[m] = _mm_fmadd_ps(_mm_set1_ps(_cvtsh_ss(half[m])), l0, even[m]);
            odd[m] = _mm_fmadd_ps(_mm_set1_ps(_cvtsh_ss(half[M + m])), l1, odd[m]);
        }
    }
    if (e < end) {
        const __m128 l0 = _mm_loadu_ps(radiance + std::size_t(positions[e]) * 4);
        for (std::uint32_t m = 0; m < M; ++m) even[m] = _mm_fmadd_ps(_mm_set1_ps(_cvtsh_ss(half[m])), l0, even[m]);
    }
    for (std::uint32_t m = 0; m < M; ++m) {
        alignas(16) float sum[4];
        _mm_store_ps(sum, _mm_mul_ps(_mm_add_ps(even[m], odd[m]), _mm_set1_ps(scales[m])));
        for (int c = 0; c < 3; ++c) out[3 * m + c] += sum[c];
    }
}

// A texel's padded RGB in both 128-bit halves of a register.
template <typename Index>
__attribute__((target("avx2,fma,f16c"))) inline __m256 texelInBothHalves(const float* radiance, Index position) {
    return _mm256_broadcast_ps(reinterpret_cast<const __m128*>(radiance + std::size_t(position) * 4));
}

// How far ahead of the entries being summed the two-moment loop prefetches their values and
// positions (prefetch.h), in entries (2 KB of values). Its irradiance moments on the
// 65,536-sample bunny's dome rotation (opal-bench relight, medians, 2026-11-28): none
// 12.6-13.8 ms; 128 entries 10.7; 256 9.4; 512 9.2.
constexpr std::size_t kPrefetchEntries = 512;

// Two moments (the bake's default), four entries at a time: their eight values converted by
// one vcvtph2ps, each entry's texel loaded into both 128-bit halves of a register and
// multiplied by its two values, spread over the halves by one permute ([m0 x 4 | m1 x 4]):
// one fused multiply-add per entry where sampleAvx2 spends two, and two scalar conversions
// and broadcasts. Four chains, one per entry of a group. Measured on the 65,536-sample bunny
// (36-function bake, 2026-11-27), `opal-bench relight`'s dome rotation: its irradiance
// moments 21.1-21.4 ms with sampleAvx2, 14.6-14.8 ms this way.
template <typename Index>
__attribute__((target("avx2,fma,f16c"))) void sampleAvx2TwoMoments(const Index* positions, const std::uint16_t* half,
                                                                   std::uint64_t begin, std::uint64_t end,
                                                                   const float* radiance, const float (&scales)[2],
                                                                   float* out) {
    const __m256i spread[4] = {_mm256_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1), _mm256_setr_epi32(2, 2, 2, 2, 3, 3, 3, 3),
                               _mm256_setr_epi32(4, 4, 4, 4, 5, 5, 5, 5), _mm256_setr_epi32(6, 6, 6, 6, 7, 7, 7, 7)};
    __m256 acc[4] = {_mm256_setzero_ps(), _mm256_setzero_ps(), _mm256_setzero_ps(), _mm256_setzero_ps()};
    std::uint64_t e = begin;
    for (; e + 4 <= end; e += 4, half += 8) {
        prefetchAhead(half, kPrefetchEntries * 2 * sizeof(std::uint16_t));
        prefetchAhead(positions + e, kPrefetchEntries * sizeof(Index));
        const __m256 v = _mm256_cvtph_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(half)));
        for (int j = 0; j < 4; ++j) {
            const __m256 texel = texelInBothHalves(radiance, positions[e + std::uint64_t(j)]);
            acc[j] = _mm256_fmadd_ps(_mm256_permutevar8x32_ps(v, spread[j]), texel, acc[j]);
        }
    }
    for (; e < end; ++e, half += 2) {
        const __m256 v = _mm256_set_m128(_mm_set1_ps(_cvtsh_ss(half[1])), _mm_set1_ps(_cvtsh_ss(half[0])));
        acc[0] = _mm256_fmadd_ps(v, texelInBothHalves(radiance, positions[e]), acc[0]);
    }
    const __m256 sum = _mm256_mul_ps(_mm256_add_ps(_mm256_add_ps(acc[0], acc[1]), _mm256_add_ps(acc[2], acc[3])),
                                     _mm256_set_m128(_mm_set1_ps(scales[1]), _mm_set1_ps(scales[0])));
    alignas(32) float lanes[8];
    _mm256_store_ps(lanes, sum);
    for (int c = 0; c < 3; ++c) {
        out[c] += lanes[c];
        out[3 + c] += lanes[4 + c];
    }
}
#endif

}  // namespace

EnvironmentVectors::EnvironmentVectors(const EnvironmentTransfer& transfer, std::size_t samples, bool useAvx2)
    : terms_(transfer.fresnelTerms), kind_(transfer.kind), basis_(transfer.fresnelBasis),
      faceSize_(transfer.cubeFaceSize), texels_(6u * transfer.cubeFaceSize * transfer.cubeFaceSize) {
#if OPAL_ENVIRONMENT_VECTORS_AVX2
    avx2_ = useAvx2 && cpuHasAvx2FmaF16c();
#else
    (void)useAvx2;
#endif
    const std::string context = "environment vectors: ";
    const std::uint64_t rows = std::uint64_t(samples) * terms_;
    if (transfer.offsets.empty()) throw Error(context + "the asset has no environment transfer");
    if (terms_ == 0 || terms_ > std::uint32_t(kMaxFresnelTerms))
        throw Error(context + count(terms_) + " Fresnel terms, outside [1, " + count(kMaxFresnelTerms) + "]");
    if ( transfer.offsets.size() != rows + 1 || transfer.offsets.back() != transfer.values.size() ||
        transfer.indices.size() != transfer.values.size())
        throw Error(context + count(transfer.offsets.size()) + " row offsets for " + count(samples) + " samples x " +
                    count(terms_) + " terms, or entries that do not match them");
    // One scale per m, from that moment's largest value.
    std::vector<int> exponents(terms_);
    for (std::uint32_t m = 0; m < terms_; ++m) {
        std::vector<float> values;
        for (std::size_t i = 0; i < samples; ++i) {
            const std::uint64_t r = i * terms_ + m;
            if (transfer.offsets[r] <= transfer.offsets[r + 1])
                values.insert(values.end(), transfer.values.begin() + transfer.offsets[r],
                              transfer.values.begin() + transfer.offsets[r + 1]);
        }
        for (float v : values)
            if (!std::isfinite(v)) throw Error(context + "a value is not finite");
        exponents[m] = halfScaleExponent(values);
        scales_.push_back(std::ldexp(1.0f, exponents[m]));
    }
    const std::size_t expected = transfer.values.size() / terms_;
    positions_ = CompactIndices(texels_);
    positions_.reserve(expected);
    halves_.reserve(expected * terms_);
    offsets_.reserve(samples + 1);
    offsets_.push_back(0);
    std::vector<Entry> entries;
    for (std::size_t i = 0; i < samples; ++i) {
        entries.clear();
        for (std::uint32_t m = 0; m < terms_; ++m) {
            const std::uint64_t r = i * terms_ + m;
            if (transfer.offsets[r] > transfer.offsets[r + 1])
                throw Error(context + "row offsets decrease at row " + count(r));
            for (std::uint32_t e = transfer.offsets[r]; e < transfer.offsets[r + 1]; ++e) {
                if (transfer.indices[e] >= texels_)
                    throw Error(context + "sample " + count(i) + ": texel " + count(transfer.indices[e]) +
                                " outside the " + count(texels_) + "-texel cube map");
                entries.push_back({transfer.indices[e], m, transfer.values[e]});
            }
        }
        std::sort(entries.begin(), entries.end(),
                  [](const Entry& a, const Entry& b) { return a.position != b.position ? a.position < b.position : a.m < b.m; });
        for (std::size_t j = 0; j < entries.size();) {
            const std::uint32_t position = entries[j].position;
            std::uint16_t halves[kMaxFresnelTerms] = {};
            bool any = false;
            for (; j < entries.size() && entries[j].position == position; ++j)
                any |= toNormalHalf(entries[j].value, exponents[entries[j].m], halves[entries[j].m]);
            if (!any) continue;  // every value negligible
            positions_.push_back(position);  // checked below texels
            halves_.insert(halves_.end(), halves, halves + terms_);
        }
        offsets_.push_back(positions_.size());
    }
}

// radiance: texels x 4 (RGB and a zero), so that each entry is whole-register arithmetic.
// Even and odd entries go to separate accumulators to halve the add dependency chain. Each
// m's scale times the weight, once per call, on the stack.
template <typename Index, std::uint32_t M>
void EnvironmentVectors::addRows(const Index* positions, const float* radiance, float weight,
                                 IrradianceMoments& moments) const {
    float scales[M];
    for (std::uint32_t m = 0; m < M; ++m) scales[m] = scales_[m] * weight;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples(), kSamplesPerTask), [&](const auto& range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
#if OPAL_ENVIRONMENT_VECTORS_AVX2
            if (avx2_) {
                const std::uint16_t* half = halves_.data() + offsets_[i] * M;
                float* out = moments.sample(i);
                if constexpr (M == 2)
                    sampleAvx2TwoMoments<Index>(positions, half, offsets_[i], offsets_[i + 1], radiance, scales, out);
                else
                    sampleAvx2<Index, M>(positions, half, offsets_[i], offsets_[i + 1], radiance, scales, out);
                continue;
            }
#endif
            Float4 even[M] = {}, odd[M] = {};
            const std::uint16_t* half = halves_.data() + offsets_[i] * M;
            std::uint64_t e = offsets_[i];
            const std::uint64_t stop = offsets_[i + 1];
            for (; e + 2 <= stop; e += 2, half += 2 * M) {
                const Float4 l0 = load4(radiance + std::size_t(positions[e]) * 4);
                const Float4 l1 = load4(radiance + std::size_t(positions[e + 1]) * 4);
                for (std::uint32_t m = 0; m < M; ++m) {
                    even[m] += normalHalfToFloat(half[m]) * l0;  // absent (bits 0): 2^-30 of the largest
                    odd[m] += normalHalfToFloat(half[M + m]) * l1;
                }
            }
            if (e < stop) {
                const Float4 l0 = load4(radiance + std::size_t(positions[e]) * 4);
                for (std::uint32_t m = 0; m < M; ++m) even[m] += normalHalfToFloat(half[m]) * l0;
            }
            float* out = moments.sample(i);  // [m * 3 + c]
            for (std::uint32_t m = 0; m < M; ++m) {
                const Float4 sum = (even[m] + odd[m]) * scales[m];
                for (int c = 0; c < 3; ++c) out[3 * m + c] += sum[c];
            }
        }
    });
}

void EnvironmentVectors::addDome(std::vector<float> radiance, const DomeConvolution* open,
                                 const Imath::V3f& openScale, const Imath::M33d& domeFromObject,
                                 std::span<const SurfaceSample> samples, IrradianceMoments& moments) {
    if (samples.size() != this->samples() || moments.terms != terms_ || moments.samples != this->samples())
        throw Error("dome light: the environment transfer has " + count(this->samples()) + " samples x " +
                    count(terms_) + " Fresnel terms, the asset " + count(samples.size()) + " samples, the irradiance " +
                    count(moments.samples) + " x " + count(moments.terms));
    const CubeMapLayout cube(faceSize_);
    if (kind_ == EnvironmentVectorKind::Occluded) {
        if (!open || open->terms() != terms_)
            throw Error("dome light: occluded environment vectors need the dome's unoccluded integral with " +
                        count(terms_) + " Fresnel terms");
        const Imath::M33f turn(domeFromObject);
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples.size(), kSamplesPerTask), [&](const auto& range) {
            for (std::size_t i = range.begin(); i != range.end(); ++i) open->add(samples[i].normal * turn, openScale, moments.sample(i));
        });
    }
    haarForwardCharts(std::span<float>(radiance), cube.charts(), 3);
    addIrradiance(radiance, moments, kind_ == EnvironmentVectorKind::Occluded ? -1.0f : 1.0f);
}

void EnvironmentVectors::addIrradiance(std::span<const float> haarRadiance, IrradianceMoments& moments,
                                       float weight) {
    if (moments.terms != terms_ || moments.samples != samples())
        throw Error("dome light: the environment transfer has " + count(samples()) + " samples x " + count(terms_) +
                    " Fresnel terms, the irradiance " + count(moments.samples) + " x " + count(moments.terms));
    if (haarRadiance.size() != std::size_t(texels_) * 3)
        throw Error("dome light: " + count(haarRadiance.size()) + " radiance values for " + count(texels_) +
                    " RGB texels");
    // Sized (and its fourth lanes zeroed) once; each call writes only the RGB lanes.
    padded_.resize(std::size_t(texels_) * 4, 0.0f);
    for (std::size_t t = 0; t < texels_; ++t) std::copy_n(haarRadiance.data() + 3 * t, 3, padded_.data() + 4 * t);
    const auto withTerms = [&](auto index) {
        using Index = std::remove_cv_t<std::remove_pointer_t<decltype(index)>>;
        switch (terms_) {
            case 1: addRows<Index, 1>(index, padded_.data(), weight, moments); break;
            case 2: addRows<Index, 2>(index, padded_.data(), weight, moments); break;
            default: addRows<Index, 3>(index, padded_.data(), weight, moments); break;
        }
    };
    positions_.withData(withTerms);
}

}  // namespace opal
