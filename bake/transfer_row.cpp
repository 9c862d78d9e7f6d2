#include "bake/transfer_row.h"

#include "schema/error.h"

#include <Imath/ImathVec.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace opal {

namespace {

// Columns are done in blocks small enough for the radii to stay in L1.
constexpr std::size_t kBlock = 256;

// r[j] = |x_i - x_o| for i = begin + j, as Imath's V3f::length computes it: sqrt of
// (dx dx + dy dy) + dz dz, except below 2 FLT_MIN, where it rescales to avoid underflow
// (V3f::lengthTiny). The common case vectorizes; the rare tiny ones (always the o == i
// pair) are redone with Imath itself.
void distances(const TransferSamples& s, std::size_t o, std::size_t begin, std::size_t count, float* r) {
    const float xo = s.x[o], yo = s.y[o], zo = s.z[o];
    const float* x = s.x.data() + begin;
    const float* y = s.y.data() + begin;
    const float* z = s.z.data() + begin;
    constexpr float kTiny = 2.0f * std::numeric_limits<float>::min();
    unsigned tiny = 0;  // a count, not a flag: sum reductions vectorize
    for (std::size_t j = 0; j < count; ++j) {
        const float dx = x[j] - xo, dy = y[j] - yo, dz = z[j] - zo;
        r[j] = dx * dx + dy * dy + dz * dz;
        tiny += r[j] < kTiny;
    }
    // std::sqrt may set errno, which keeps the compiler from vectorizing it; sqrtps rounds
    // the same (IEEE square roots are correctly rounded) and the squares are never < 0.
    std::size_t j = 0;
#if defined(__SSE2__)
    for (; j + 4 <= count; j += 4) _mm_storeu_ps(r + j, _mm_sqrt_ps(_mm_loadu_ps(r + j)));
#endif
    for (; j < count; ++j) r[j] = std::sqrt(r[j]);
    if (tiny == 0) return;
    for (j = 0; j < count; ++j) {
        const Imath::V3f d(x[j] - xo, y[j] - yo, z[j] - zo);
        if (d.length2() < kTiny) r[j] = d.length();
    }
}

}  // namespace

TransferSamples toTransferSamples(std::span<const SurfaceSample> samples, double unitsPerMm) {
    if (!(unitsPerMm > 0.0 && std::isfinite(unitsPerMm)))
        throw Error("transfer: units per mm must be positive and finite, got " + std::to_string(unitsPerMm));
    const float toMm = float(1.0 / unitsPerMm);
    TransferSamples mm;
    const std::size_t n = samples.size();
    mm.x.resize(n);
    mm.y.resize(n);
    mm.z.resize(n);
    mm.area.resize(n);
    mm.harmonicSet = harmonicSetFor(samples);
    const std::size_t Q = mm.harmonicSet.count;
    mm.harmonics.assign(Q, std::vector<float>(n));
    std::array<float, kMaxHarmonics> f;
    for (std::size_t i = 0; i < n; ++i) {
        harmonicValues(mm.harmonicSet, samples[i], std::span<float>(f.data(), Q));
        for (std::size_t q = 0; q < Q; ++q) mm.harmonics[q][i] = f[q];
        mm.x[i] = samples[i].position.x * toMm;
        mm.y[i] = samples[i].position.y * toMm;
        mm.z[i] = samples[i].position.z * toMm;
        mm.area[i] = samples[i].area * toMm * toMm;
    }
    return mm;
}

namespace {

constexpr std::size_t kHarmonicLanes = 16;

// acc[q][l] += sum over i = begin + l (mod 16) of row[i] y_q[i], q < 9, for i in [begin, end)
// with end - begin a multiple of 16: nine sums (one group of the set's functions) share
// each load of the row. Each lane adds in the same order on every CPU (no reassociation),
// so a machine gives the same bits whatever the split of the rows (farm shards). The nine
// accumulators are whole vectors held in registers: written as arrays indexed by q, GCC
// kept them in memory, a store and a reload per multiply-add (measured with the 36
// functions: the 16,384-sample candle's transfer stage 14.1-14.7 s that way, 10.8 s this
// way with blocks of 1,024 samples; 12.3 s with 2,048, 11.9 s with 512).
using HarmonicVector = float __attribute__((vector_size(kHarmonicLanes * sizeof(float))));

__attribute__((target_clones("avx512f", "avx2", "default"))) void harmonicLanes(
    const float* row, const float* const* y, std::size_t begin, std::size_t end,
    float (&acc)[kNormalHarmonics][kHarmonicLanes]) {
    // By reference: a 64-byte vector passed or returned by value changes the ABI between
    // the clones (GCC's -Wpsabi).
    const auto multiplyAdd = [](HarmonicVector& a, const HarmonicVector& r, const float* y) {
        HarmonicVector v;
        std::memcpy(&v, y, sizeof(v));
        a += r * v;
    };
    HarmonicVector a0{}, a1{}, a2{}, a3{}, a4{}, a5{}, a6{}, a7{}, a8{};
    const float *y0 = y[0], *y1 = y[1], *y2 = y[2], *y3 = y[3], *y4 = y[4], *y5 = y[5], *y6 = y[6], *y7 = y[7],
                *y8 = y[8];
    for (std::size_t i = begin; i < end; i += kHarmonicLanes) {
        HarmonicVector r;
        std::memcpy(&r, row + i, sizeof(r));
        multiplyAdd(a0, r, y0 + i);
        multiplyAdd(a1, r, y1 + i);
        multiplyAdd(a2, r, y2 + i);
        multiplyAdd(a3, r, y3 + i);
        multiplyAdd(a4, r, y4 + i);
        multiplyAdd(a5, r, y5 + i);
        multiplyAdd(a6, r, y6 + i);
        multiplyAdd(a7, r, y7 + i);
        multiplyAdd(a8, r, y8 + i);
    }
    const HarmonicVector sums[kNormalHarmonics] = {a0, a1, a2, a3, a4, a5, a6, a7, a8};
    for (std::size_t q = 0; q < kNormalHarmonics; ++q)
        for (std::size_t l = 0; l < kHarmonicLanes; ++l) acc[q][l] += sums[q][l];
}

}  // namespace

void harmonicRow(std::span<const float> rows, std::size_t stride, std::size_t K, const TransferSamples& samples,
                 std::span<float> h) {
    const std::size_t n = samples.size(), Q = samples.harmonics.size();
    if (K == 0 || stride < n || rows.size() < (K - 1) * stride + n || h.size() != K * Q || Q % kNormalHarmonics != 0 ||
        Q > kMaxHarmonics)
        throw Error("harmonicRow: " + std::to_string(rows.size()) + " row values (stride " + std::to_string(stride) +
                    ") and " + std::to_string(h.size()) + " sums do not fit K = " + std::to_string(K) + " rows of " +
                    std::to_string(n) + " samples and " + std::to_string(Q) + " functions");
    constexpr std::size_t kBlock = 1024;  // a block of nine planes: 36 KiB, in L1
    std::array<const float*, kMaxHarmonics> y;
    for (std::size_t q = 0; q < Q; ++q) y[q] = samples.harmonics[q].data();
    std::vector<double> sums(K * Q, 0.0);
    for (std::size_t begin = 0; begin < n; begin += kBlock) {
        const std::size_t end = std::min(n, begin + kBlock), whole = begin + (end - begin) / kHarmonicLanes * kHarmonicLanes;
        for (std::size_t g = 0; g < Q; g += kNormalHarmonics)
            for (std::size_t k = 0; k < K; ++k) {
                const float* row = rows.data() + k * stride;
                float acc[kNormalHarmonics][kHarmonicLanes] = {};
                harmonicLanes(row, y.data() + g, begin, whole, acc);
                for (std::size_t q = 0; q < kNormalHarmonics; ++q) {
                    double sum = 0.0;
                    for (float v : acc[q]) sum += double(v);
                    for (std::size_t i = whole; i < end; ++i) sum += double(row[i]) * double(y[g + q][i]);
                    sums[k * Q + g + q] += sum;
                }
            }
    }
    for (std::size_t i = 0; i < sums.size(); ++i) h[i] = float(sums[i]);
}

void transferRow(std::size_t o, const TransferSamples& samples, const BasisLookup& lookup,
                 std::span<float> rows, std::size_t stride) {
    const std::size_t n = samples.size(), K = std::size_t(lookup.K());
    if (o >= n)
        throw Error("transferRow: output sample " + std::to_string(o) + " is not below the " +
                    std::to_string(n) + " samples");
    if (stride < n || rows.size() != (K - 1) * stride + n)
        throw Error("transferRow: buffer of " + std::to_string(rows.size()) + " floats with row stride " +
                    std::to_string(stride) + ", expected (K - 1) x stride + N = " + std::to_string(K - 1) + " x " +
                    std::to_string(stride) + " + " + std::to_string(n) + " (stride >= N)");
    float r[kBlock];
    for (std::size_t first = 0; first < n; first += kBlock) {
        const std::size_t count = std::min(kBlock, n - first);
        distances(samples, o, first, count, r);
        lookup.evaluateWeighted(std::span<const float>(r, count),
                                std::span<const float>(samples.area).subspan(first, count), rows.data() + first,
                                stride);
    }
}

void transferRow(std::size_t o, const TransferSamples& samples, const BasisLookup& lookup,
                 std::span<float> rows) {
    transferRow(o, samples, lookup, rows, samples.size());
}

std::size_t transferRowStride(std::size_t n) {
    constexpr std::size_t kLine = 64 / sizeof(float);
    return (n + kLine - 1) / kLine * kLine + kLine;
}

}  // namespace opal
