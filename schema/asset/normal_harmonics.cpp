#include "schema/asset/normal_harmonics.h"

#include "schema/error.h"
#include "schema/target_clones.h"

#include <eigen3/Eigen/Dense>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace opal {

std::array<float, kNormalHarmonics> normalHarmonics(const Imath::V3f& n) {
    return {1.0f, n.x, n.y, n.z, n.x * n.y, n.y * n.z, 3.0f * n.z * n.z - 1.0f, n.x * n.z, n.x * n.x - n.y * n.y};
}

bool isHarmonicCount(std::uint64_t count) { return count == kNormalHarmonics || count == kMaxHarmonics; }

void harmonicValues(const HarmonicSet& set, const SurfaceSample& sample, std::span<float> out) {
    if (!isHarmonicCount(set.count) || out.size() != set.count)
        throw Error("harmonic functions: a set of " + std::to_string(set.count) + " functions (9 or 36) into " +
                    std::to_string(out.size()) + " values");
    const std::array<float, kNormalHarmonics> y = normalHarmonics(sample.normal);
    std::copy(y.begin(), y.end(), out.begin());
    if (set.count == kNormalHarmonics) return;
    const Imath::V3f p = (sample.position - set.centre) * set.inverseScale;
    for (std::size_t b = 1; b < kPositionFactors; ++b)
        for (std::size_t h = 0; h < kNormalHarmonics; ++h) out[b * kNormalHarmonics + h] = y[h] * p[int(b - 1)];
}

HarmonicSet harmonicSetFor(std::span<const SurfaceSample> samples) {
    HarmonicSet set;
    set.count = std::uint32_t(kMaxHarmonics);
    if (samples.empty()) return set;
    Imath::V3f low(std::numeric_limits<float>::max()), high(std::numeric_limits<float>::lowest());
    for (const SurfaceSample& s : samples)
        for (int a = 0; a < 3; ++a) {
            low[a] = std::min(low[a], s.position[a]);
            high[a] = std::max(high[a], s.position[a]);
        }
    set.centre = (low + high) * 0.5f;
    const float half = 0.5f * std::max({high.x - low.x, high.y - low.y, high.z - low.z});
    set.inverseScale = half > 0.0f ? 1.0f / half : 1.0f;
    return set;
}

HarmonicFit::HarmonicFit(std::span<const SurfaceSample> samples, const HarmonicSet& set)
    : count_(set.count), patterns_(samples.size() * set.count) {
    if (!isHarmonicCount(set.count))
        throw Error("harmonic fit: a set of " + std::to_string(set.count) + " functions, expected 9 or 36");
    const auto Q = Eigen::Index(count_);
    Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(Q, Q);
    Eigen::VectorXd v(Q);
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const std::span<float> f(patterns_.data() + i * count_, count_);
        harmonicValues(set, samples[i], f);
        for (Eigen::Index q = 0; q < Q; ++q) v[q] = f[std::size_t(q)];
        gram.selfadjointView<Eigen::Lower>().rankUpdate(v);
    }
    gram.triangularView<Eigen::StrictlyUpper>() = gram.transpose();
    // Eigen's default rank threshold: a flat patch (every normal the same) leaves only Y_0 and
    // the constant combinations, which the pseudo-inverse solves with the minimum norm.
    const Eigen::MatrixXd inverse = Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(gram).pseudoInverse();
    solve_.resize(count_ * count_);
    for (Eigen::Index r = 0; r < Q; ++r)
        for (Eigen::Index c = 0; c < Q; ++c) solve_[std::size_t(r * Q + c)] = inverse(r, c);
}

namespace {

using RowMajor = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using Rows = Eigen::Map<const RowMajor>;

// Blocks of samples for the fit's two products, in float, the blocks' sums added in double.
// The split is exact for any coefficients (normal_harmonics.h), so their float rounding
// moves only what the matrices carry, never the result's consistency.
constexpr std::size_t kFitBlock = 2048;

// The channel counts a light edit fits with one or two Fresnel moments (3 or 6; two is the
// bake's default) run with a sample's channels as one vector: per sample, one multiply and
// add per function, the function's value broadcast, the sums in registers. Other counts go
// through Eigen's float GEMMs, which took 1.3 and 1.2 ms for the two products of a light
// move on the 65,536-sample bunny (36 functions, 6 channels; these loops 0.7 and 0.6-0.8).

// Up to eight channels of one sample in a vector.
using Lanes8 = float __attribute__((vector_size(8 * sizeof(float))));

// Row i's C <= 8 values in a vector. The first `wide` rows are read eight values at a time
// (the lanes beyond C hold the next row's values, which no caller uses: they meet only zeros
// or are never stored); the rows after them, whose wide read would run past the values, are
// read value by value.
template <std::size_t C>
inline void loadRow(const float* v, std::size_t i, std::size_t wide, Lanes8& row) {
    row = Lanes8{};
    if (i < wide) {
        std::memcpy(&row, v + i * C, sizeof(row));
    } else {
        for (std::size_t c = 0; c < C; ++c) row[c] = v[i * C + c];
    }
}

// sums[q * C + c] += sum over the block's rows i of f[i Q + q] v[i C + c], the functions
// twelve at a time. Compiled per target, as subtractFit (schema/target_clones.h).
template <std::size_t Q, std::size_t C>
OPAL_TARGET_CLONES("avx512f", "avx2", "default") void addProducts(const float* f, const float* v, std::size_t rows,
                                                                 std::size_t wide, double* sums) {
    static_assert(C <= 8);
    constexpr std::size_t Chunk = Q % 12 == 0 ? 12 : Q;
    for (std::size_t q0 = 0; q0 < Q; q0 += Chunk) {
        Lanes8 acc[Chunk] = {};
        for (std::size_t i = 0; i < rows; ++i) {
            Lanes8 row;
            loadRow<C>(v, i, wide, row);
            for (std::size_t q = 0; q < Chunk; ++q) acc[q] += f[i * Q + q0 + q] * row;
        }
        for (std::size_t q = 0; q < Chunk; ++q)
            for (std::size_t c = 0; c < C; ++c) sums[(q0 + q) * C + c] += double(acc[q][c]);
    }
}

// out[i stride + c] = v[i C + c] - sum_q f[i Q + q] a[q C + c] over the block's rows.
template <std::size_t Q, std::size_t C>
OPAL_TARGET_CLONES("avx512f", "avx2", "default") void subtractFit(const float* f, const float* v, const float* a,
                                                                 std::size_t rows, std::size_t wide, float* out,
                                                                 std::size_t stride) {
    static_assert(C <= 8);
    Lanes8 aq[Q] = {};
    for (std::size_t q = 0; q < Q; ++q)
        for (std::size_t c = 0; c < C; ++c) aq[q][c] = a[q * C + c];
    for (std::size_t i = 0; i < rows; ++i) {
        Lanes8 r;
        loadRow<C>(v, i, wide, r);
        for (std::size_t q = 0; q < Q; ++q) r -= f[i * Q + q] * aq[q];
        for (std::size_t c = 0; c < C; ++c) out[i * stride + c] = r[c];
    }
}

// Of `rows` rows of C values starting at row `first` of `total` rows, how many can be read
// eight values at a time (loadRow) without running past the last value.
template <std::size_t C>
std::size_t wideRows(std::size_t first, std::size_t rows, std::size_t total) {
    std::size_t wide = rows;
    while (wide > 0 && (first + wide - 1) * C + 8 > total * C) --wide;
    return wide;
}

// call(std::integral_constant<Q>, std::integral_constant<C>) for the fit's Q (9 or 36) and
// C of 3 or 6; false (nothing called) for any other C.
template <typename Call>
bool withFixedSizes(std::size_t Q, std::size_t C, Call&& call) {
    const auto forQ = [&](auto q) {
        switch (C) {
            case 3: call(q, std::integral_constant<std::size_t, 3>{}); return true;
            case 6: call(q, std::integral_constant<std::size_t, 6>{}); return true;
            default: return false;
        }
    };
    return Q == kNormalHarmonics ? forQ(std::integral_constant<std::size_t, kNormalHarmonics>{})
                                 : forQ(std::integral_constant<std::size_t, kMaxHarmonics>{});
}

}  // namespace

std::vector<float> HarmonicFit::coefficients(std::span<const float> values, std::size_t C) const {
    const std::size_t n = samples(), Q = count_;
    if (C == 0 || values.size() != n * C)
        throw Error("harmonic fit: " + std::to_string(values.size()) + " values for " + std::to_string(n) +
                    " samples of " + std::to_string(C) + " channels");
    // b = F^T V (Q x C), F the samples' f_q (n x Q), V the values (n x C).
    using Sums = Eigen::MatrixXd;
    const Sums b = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, n, kFitBlock), Sums(Sums::Zero(Eigen::Index(Q), Eigen::Index(C))),
        [&](const tbb::blocked_range<std::size_t>& r, Sums sums) {
            const float* f = patterns_.data() + r.begin() * Q;
            const float* v = values.data() + r.begin() * C;
            std::vector<double> block(Q * C, 0.0);  // [q C + c]
            const bool fixed = withFixedSizes(Q, C, [&](auto q, auto c) {
                constexpr std::size_t channels = decltype(c)::value;
                addProducts<decltype(q)::value, channels>(f, v, r.size(), wideRows<channels>(r.begin(), r.size(), n),
                                                          block.data());
            });
            if (!fixed) {
                const auto rows = Eigen::Index(r.size());
                const Eigen::MatrixXf product = Rows(f, rows, Eigen::Index(Q)).transpose() * Rows(v, rows, Eigen::Index(C));
                for (std::size_t q = 0; q < Q; ++q)
                    for (std::size_t c = 0; c < C; ++c) block[q * C + c] = product(Eigen::Index(q), Eigen::Index(c));
            }
            for (std::size_t q = 0; q < Q; ++q)
                for (std::size_t c = 0; c < C; ++c) sums(Eigen::Index(q), Eigen::Index(c)) += block[q * C + c];
            return sums;
        },
        [](Sums a, const Sums& b) { return Sums(a + b); });
    std::vector<float> a(Q * C);
    for (std::size_t q = 0; q < Q; ++q)
        for (std::size_t c = 0; c < C; ++c) {
            double sum = 0.0;
            for (std::size_t r = 0; r < Q; ++r) sum += solve_[q * Q + r] * b(Eigen::Index(r), Eigen::Index(c));
            a[q * C + c] = float(sum);
        }
    return a;
}

void HarmonicFit::residual(std::span<const float> values, std::size_t C, std::span<const float> a,
                           std::span<float> residual, std::size_t stride) const {
    const std::size_t n = samples(), Q = count_;
    if (C == 0 || stride < C || values.size() != n * C || a.size() != Q * C ||
        residual.size() < (n == 0 ? 0 : (n - 1) * stride + C))
        throw Error("harmonic fit: residual of " + std::to_string(values.size()) + " values (" + std::to_string(C) +
                    " channels, stride " + std::to_string(stride) + ") does not fit " + std::to_string(n) +
                    " samples");
    const Rows coefficients(a.data(), Eigen::Index(Q), Eigen::Index(C));
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kFitBlock), [&](const tbb::blocked_range<std::size_t>& r) {
        const float* f = patterns_.data() + r.begin() * Q;
        const float* v = values.data() + r.begin() * C;
        float* to = residual.data() + r.begin() * stride;
        const bool fixed = withFixedSizes(Q, C, [&](auto q, auto c) {
            constexpr std::size_t channels = decltype(c)::value;
            subtractFit<decltype(q)::value, channels>(f, v, a.data(), r.size(), wideRows<channels>(r.begin(), r.size(), n),
                                                      to, stride);
        });
        if (fixed) return;
        const auto rows = Eigen::Index(r.size());
        Eigen::Map<RowMajor, 0, Eigen::OuterStride<>> out(to, rows, Eigen::Index(C), Eigen::OuterStride<>(Eigen::Index(stride)));
        out.noalias() = Rows(v, rows, Eigen::Index(C)) - Rows(f, rows, Eigen::Index(Q)) * coefficients;
    });
}

}  // namespace opal
