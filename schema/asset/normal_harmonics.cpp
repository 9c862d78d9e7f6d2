#include "schema/asset/normal_harmonics.h"

#include "schema/error.h"

#include <eigen3/Eigen/Dense>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <limits>
#include <string>

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

// Blocks of samples for the fit's two products: each a float GEMM (Eigen), the blocks'
// sums added in double. The split is exact for any coefficients (normal_harmonics.h), so
// their float rounding moves only what the matrices carry, never the result's consistency.
constexpr std::size_t kFitBlock = 2048;

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
            const auto rows = Eigen::Index(r.size());
            const Rows f(patterns_.data() + r.begin() * Q, rows, Eigen::Index(Q));
            const Rows v(values.data() + r.begin() * C, rows, Eigen::Index(C));
            const Eigen::MatrixXf block = f.transpose() * v;
            sums += block.cast<double>();
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
        const auto rows = Eigen::Index(r.size());
        const Rows f(patterns_.data() + r.begin() * Q, rows, Eigen::Index(Q));
        const Rows v(values.data() + r.begin() * C, rows, Eigen::Index(C));
        Eigen::Map<RowMajor, 0, Eigen::OuterStride<>> out(residual.data() + r.begin() * stride, rows, Eigen::Index(C),
                                                          Eigen::OuterStride<>(Eigen::Index(stride)));
        out.noalias() = v - f * coefficients;
    });
}

}  // namespace opal
