// Coefficient selection for the two compression steps (docs/ARCHITECTURE.md#compression): step 1
// keeps the largest Haar coefficients of each transfer row, step 2 keeps the 9/7
// coefficients carrying a given fraction of the energy.
#include "schema/wavelet/sparse.h"

#include "schema/error.h"
#include "schema/wavelet/scratch.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace opal {

namespace {

void checkLength(std::string_view function, std::size_t length) {
    if (length > std::numeric_limits<std::uint32_t>::max())
        throw Error(std::string(function) + ": " + std::to_string(length) +
                    " coefficients do not fit 32-bit indices");
}

void checkFinite(std::string_view function, std::string_view what, std::span<const float> values) {
    bool allFinite = true;
    for (float v : values) allFinite &= std::isfinite(v);  // no early exit: vectorizes
    if (allFinite) return;
    for (std::size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i]))
            throw Error(std::string(function) + ": " + std::string(what) + " " + std::to_string(i) +
                        " is not finite (" + std::to_string(values[i]) + ")");
}

// The k-th largest score (k >= 1) and how many of the k largest are strictly above it;
// the remaining k - above are ties at `value`, taken by lower index.
template <typename V>
struct Threshold {
    V value = 0;
    std::size_t above = 0;
};

// The coefficients with the k largest scores, ties at the threshold broken by lower
// index, in one ascending pass (so no sort of the result is needed).
template <typename V, typename Score>
SparseVector collect(std::span<const float> dense, Score score, Threshold<V> threshold,
                     std::size_t k) {
    SparseVector result;
    result.indices.reserve(k);
    result.values.reserve(k);
    std::size_t ties = k - threshold.above;
    for (std::uint32_t i = 0; i < dense.size(); ++i) {
        const V s = score(i);
        bool take = s > threshold.value;
        if (!take && s == threshold.value && ties > 0) {
            take = true;
            --ties;
        }
        if (take) {
            result.indices.push_back(i);
            result.values.push_back(dense[i]);
        }
    }
    return result;
}

// The threshold of the k largest values once values[0, k) holds them (in any order).
template <typename V>
Threshold<V> thresholdOfTop(std::span<const V> values, std::size_t k) {
    const V kth = *std::min_element(values.begin(), values.begin() + k);
    return {kth, std::size_t(std::count_if(values.begin(), values.begin() + k,
                                           [&](V v) { return v > kth; }))};
}

// Reorder `values` (all > 0) so that its first k entries are the k largest, for the
// smallest k whose sum reaches `target`; return k and the threshold. Halving selection
// with std::nth_element on contiguous values: expected O(n), no full sort.
std::pair<std::size_t, Threshold<double>> selectFewestReaching(std::span<double> values,
                                                               double target) {
    constexpr std::size_t kSortBelow = 64;
    const auto larger = std::greater<double>();
    std::size_t lo = 0, hi = values.size();  // values[0, lo) are taken; k is in (lo, hi]
    double need = target;
    while (hi - lo > kSortBelow) {
        const std::size_t mid = lo + (hi - lo) / 2;
        std::nth_element(values.begin() + lo, values.begin() + mid, values.begin() + hi, larger);
        const double upper = std::accumulate(values.begin() + lo, values.begin() + mid, 0.0);
        if (upper >= need) {
            hi = mid;
        } else {
            need -= upper;
            lo = mid;
        }
    }
    std::sort(values.begin() + lo, values.begin() + hi, larger);
    std::size_t k = hi;  // if rounding keeps `need` above 0, everything left is needed
    for (std::size_t j = lo; j < hi; ++j) {
        need -= values[j];
        if (need <= 0) {
            k = j + 1;
            break;
        }
    }
    return {k, thresholdOfTop<double>(values, k)};
}

// keepLargest's ranking: magnitude first, then lower index. For finite floats the bit
// pattern of |c| (sign cleared) orders like |c|, so the rank of coefficient i is the
// integer key (|c_i| bits, 2^32 - 1 - i), larger first; keys are unique.
std::uint32_t magnitudeBits(float c) { return std::bit_cast<std::uint32_t>(c) & 0x7fffffffu; }
std::uint64_t rankKey(std::uint32_t bits, std::uint32_t i) {
    return (std::uint64_t(bits) << 32) | (std::numeric_limits<std::uint32_t>::max() - i);
}

// Coefficients binned by the top 10 bits of |c| (8 exponent bits, 2 mantissa bits: a
// quarter octave per bin). Bins from kNonFiniteBin on hold infinities and NaNs.
constexpr int kMagnitudeShift = 21;
constexpr std::size_t kMagnitudeBins = std::size_t(1) << (31 - kMagnitudeShift);
constexpr std::size_t kNonFiniteBin = 0x7f800000u >> kMagnitudeShift;

struct MagnitudeHistogram {
    std::array<std::uint32_t, kMagnitudeBins> count{};  // zeros included in bin 0
    std::size_t zeros = 0;
};

// Four interleaved partial histograms, so that runs of equal bins do not serialize on
// one counter.
MagnitudeHistogram magnitudeHistogram(std::span<const float> dense) {
    std::array<std::array<std::uint32_t, kMagnitudeBins>, 4> partial{};
    std::size_t zeros = 0, i = 0;
    for (; i + 4 <= dense.size(); i += 4)
        for (std::size_t lane = 0; lane < 4; ++lane) {
            const std::uint32_t bits = magnitudeBits(dense[i + lane]);
            ++partial[lane][bits >> kMagnitudeShift];
            zeros += bits == 0;
        }
    for (; i < dense.size(); ++i) {
        const std::uint32_t bits = magnitudeBits(dense[i]);
        ++partial[0][bits >> kMagnitudeShift];
        zeros += bits == 0;
    }
    MagnitudeHistogram h;
    for (std::size_t b = 0; b < kMagnitudeBins; ++b)
        h.count[b] = partial[0][b] + partial[1][b] + partial[2][b] + partial[3][b];
    h.zeros = zeros;
    return h;
}

// The n largest by rank (0 < n < nonzeros, all finite): the histogram gives the bin
// holding the n-th largest; everything in higher bins is kept, and the remaining places
// go to the best-ranked coefficients of that boundary bin, found by selection over their
// keys (the only values ever compared one by one).
SparseVector largestBySelection(std::span<const float> dense, std::size_t n, const MagnitudeHistogram& h) {
    std::size_t boundary = kNonFiniteBin, above = 0;
    while (above + h.count[boundary - 1] < n) above += h.count[--boundary];
    --boundary;  // bins above `boundary` hold `above` < n coefficients, with it >= n
    const std::size_t inBoundary = h.count[boundary] - (boundary == 0 ? h.zeros : 0);
    const std::size_t need = n - above;

    std::span<std::uint32_t> indices = wavelet_detail::threadScratch<std::uint32_t>(above + inBoundary);
    std::span<std::uint64_t> keys = wavelet_detail::threadScratch<std::uint64_t>(inBoundary);
    std::size_t taken = 0, candidates = 0;
    for (std::uint32_t i = 0; i < dense.size(); ++i) {
        const std::uint32_t bits = magnitudeBits(dense[i]);
        const std::size_t bin = bits >> kMagnitudeShift;
        if (bin > boundary) {
            indices[taken++] = i;
        } else if (bin == boundary && bits != 0) {
            indices[above + candidates] = i;
            keys[candidates++] = rankKey(bits, i);
        }
    }
    std::nth_element(keys.begin(), keys.begin() + (need - 1), keys.end(), std::greater<std::uint64_t>());
    const std::uint64_t lastKept = keys[need - 1];

    // Merge the two ascending index lists: everything above, the chosen candidates.
    SparseVector result;
    result.indices.reserve(n);
    result.values.reserve(n);
    std::size_t a = 0;
    for (std::size_t c = above; c < above + inBoundary; ++c) {
        const std::uint32_t i = indices[c];
        if (rankKey(magnitudeBits(dense[i]), i) < lastKept) continue;
        for (; a < above && indices[a] < i; ++a) result.indices.push_back(indices[a]);
        result.indices.push_back(i);
    }
    for (; a < above; ++a) result.indices.push_back(indices[a]);
    for (std::uint32_t i : result.indices) result.values.push_back(dense[i]);
    return result;
}

// The fast route of keepLargest. Most of a transfer row's Haar coefficients are far below
// its largest 1%, so: estimate from a sample a magnitude floor that about 1.5 n
// coefficients reach, collect those (one vectorized scan), and rank only
// them. The result is exact whatever the sample says; a floor that turns out too high
// (fewer than n reach it) sends keepLargest to the histogram route.
constexpr std::uint32_t kInfinityBits = 0x7f800000u;
// The sample: every 7th value (odd, because Mallat layouts repeat with power-of-two
// periods), binned by the top 11 bits of |c| (an eighth of an octave per bin) into four
// partial histograms, so that runs of equal bins do not serialize on one counter.
constexpr std::size_t kSampleStride = 7;
constexpr int kSampleShift = 20;
constexpr std::size_t kSampleBins = std::size_t(1) << (31 - kSampleShift);

// The lower edge of the sample histogram's bin where the 1.5 n S / N + 8 largest of the S
// sampled magnitudes are reached (about 1.5 n of all N reach it); in [1, kInfinityBits] so
// that zeros are never and non-finite values always collected.
std::uint32_t sampledFloor(std::span<const float> dense, std::size_t n) {
    std::array<std::array<std::uint32_t, kSampleBins>, 4> partial{};
    std::size_t i = 0;
    for (; i + 3 * kSampleStride < dense.size(); i += 4 * kSampleStride)
        for (std::size_t lane = 0; lane < 4; ++lane)
            ++partial[lane][magnitudeBits(dense[i + lane * kSampleStride]) >> kSampleShift];
    for (; i < dense.size(); i += kSampleStride) ++partial[0][magnitudeBits(dense[i]) >> kSampleShift];
    const std::size_t samples = (dense.size() + kSampleStride - 1) / kSampleStride;
    const double expected = 1.5 * double(n) * double(samples) / double(dense.size());
    const std::size_t rank = std::min(samples, std::size_t(std::ceil(expected)) + 8);
    std::size_t bin = kSampleBins, reached = 0;
    while (bin > 0 && reached < rank) {
        --bin;
        reached += partial[0][bin] + partial[1][bin] + partial[2][bin] + partial[3][bin];
    }
    return std::clamp(std::uint32_t(bin << kSampleShift), 1u, kInfinityBits);
}

// Writes the indices i (ascending) with magnitudeBits(dense[i]) >= floor to out; returns
// how many. Few qualify, but spread over the whole row (every chart and level has some),
// so the scan tests 16 values at a time (SSE: one 16-bit mask) and walks only the set bits.
std::size_t collectAtLeast(std::span<const float> dense, std::uint32_t floor, std::uint32_t* out) {
    std::size_t count = 0, i = 0;
#if defined(__SSE2__)
    const __m128i magnitude = _mm_set1_epi32(0x7fffffff);
    const __m128i below = _mm_set1_epi32(std::int32_t(floor - 1));  // magnitudes fit in 31 bits
    for (; i + 16 <= dense.size(); i += 16) {
        unsigned hits = 0;
        for (int q = 0; q < 4; ++q) {
            const __m128i v = _mm_and_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(dense.data() + i + 4 * q)),
                                            magnitude);
            hits |= unsigned(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpgt_epi32(v, below)))) << (4 * q);
        }
        for (; hits != 0; hits &= hits - 1) out[count++] = std::uint32_t(i + std::countr_zero(hits));
    }
#endif
    for (; i < dense.size(); ++i)
        if (magnitudeBits(dense[i]) >= floor) out[count++] = std::uint32_t(i);
    return count;
}

// The n best-ranked of the candidates (ascending indices, at least n of them, all
// finite and nonzero), indices ascending: selection over their rank keys finds the n-th
// key, then one pass keeps the candidates at or above it.
SparseVector bestRanked(std::span<const float> dense, std::span<const std::uint32_t> candidates, std::size_t n) {
    std::uint64_t lastKept = 0;
    if (candidates.size() > n) {
        std::span<std::uint64_t> keys = wavelet_detail::threadScratch<std::uint64_t>(candidates.size());
        for (std::size_t c = 0; c < candidates.size(); ++c)
            keys[c] = rankKey(magnitudeBits(dense[candidates[c]]), candidates[c]);
        std::nth_element(keys.begin(), keys.begin() + (n - 1), keys.end(), std::greater<std::uint64_t>());
        lastKept = keys[n - 1];
    }
    SparseVector result;
    result.indices.reserve(n);
    result.values.reserve(n);
    for (std::uint32_t i : candidates)
        if (rankKey(magnitudeBits(dense[i]), i) >= lastKept) {
            result.indices.push_back(i);
            result.values.push_back(dense[i]);
        }
    return result;
}

}  // namespace

SparseVector keepLargest(std::span<const float> dense, std::size_t n) {
    checkLength("keepLargest", dense.size());
    if (n == 0 || dense.empty()) {
        checkFinite("keepLargest", "coefficient", dense);
        return {};
    }
    // Fast route: the few coefficients above a sampled floor, ranked among themselves.
    const std::uint32_t floor = sampledFloor(dense, n);
    std::span<std::uint32_t> candidates = wavelet_detail::threadScratch<std::uint32_t>(dense.size());
    candidates = candidates.first(collectAtLeast(dense, floor, candidates.data()));
    for (std::uint32_t i : candidates)  // every non-finite value is a candidate
        if (magnitudeBits(dense[i]) >= kInfinityBits) checkFinite("keepLargest", "coefficient", dense);  // throws
    if (candidates.size() >= n) return bestRanked(dense, candidates, n);

    // Fewer than n reach the floor (or there are fewer than n nonzeros): the exact route.
    const MagnitudeHistogram histogram = magnitudeHistogram(dense);
    const std::size_t nonZeros = dense.size() - histogram.zeros;
    auto magnitude = [&](std::uint32_t i) { return std::abs(dense[i]); };
    if (n >= nonZeros) return collect(dense, magnitude, Threshold<float>{0.0f, nonZeros}, nonZeros);
    return largestBySelection(dense, n, histogram);
}

SparseVector keepEnergyFraction(std::span<const float> dense, double fraction,
                                std::span<const float> normsSquared) {
    checkLength("keepEnergyFraction", dense.size());
    if (!(fraction >= 0.0 && fraction <= 1.0))
        throw Error("keepEnergyFraction: fraction " + std::to_string(fraction) +
                    " is not in [0, 1]");
    if (!normsSquared.empty() && normsSquared.size() != dense.size())
        throw Error("keepEnergyFraction: " + std::to_string(normsSquared.size()) + " norms for " +
                    std::to_string(dense.size()) + " coefficients");
    checkFinite("keepEnergyFraction", "coefficient", dense);
    checkFinite("keepEnergyFraction", "norm", normsSquared);
    for (std::size_t i = 0; i < normsSquared.size(); ++i)
        if (normsSquared[i] < 0.0f)
            throw Error("keepEnergyFraction: norm " + std::to_string(i) + " is negative");

    // e_i = c_i^2 g_i, in double so that sums of many small energies stay accurate.
    auto energy = [&](std::uint32_t i) {
        const double c = dense[i];
        return c * c * (normsSquared.empty() ? 1.0 : double(normsSquared[i]));
    };
    std::span<double> energies = wavelet_detail::threadScratch<double>(dense.size());
    std::size_t count = 0;
    for (std::uint32_t i = 0; i < dense.size(); ++i)
        if (const double e = energy(i); e > 0.0) energies[count++] = e;
    energies = energies.first(count);
    if (fraction == 0.0 || count == 0) return {};
    if (fraction == 1.0) return collect(dense, energy, Threshold<double>{0.0, count}, count);

    const double total = std::accumulate(energies.begin(), energies.end(), 0.0);
    const auto [k, threshold] = selectFewestReaching(energies, fraction * total);
    return collect(dense, energy, threshold, k);
}

}  // namespace opal
