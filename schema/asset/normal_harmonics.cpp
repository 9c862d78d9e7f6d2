#include "schema/asset/normal_harmonics.h"

#include "schema/error.h"

#include <eigen3/Eigen/Dense>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <string>

namespace opal {

std::array<float, kNormalHarmonics> normalHarmonics(const Imath::V3f& n) {
    return {1.0f, n.x, n.y, n.z, n.x * n.y, n.y * n.z, 3.0f * n.z * n.z - 1.0f, n.x * n.z, n.x * n.x - n.y * n.y};
}

HarmonicFit::HarmonicFit(std::span<const SurfaceSample> samples) : patterns_(samples.size() * kNormalHarmonics) {
    Eigen::Matrix<double, kNormalHarmonics, kNormalHarmonics> gram = Eigen::Matrix<double, 9, 9>::Zero();
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const std::array<float, kNormalHarmonics> y = normalHarmonics(samples[i].normal);
        std::copy(y.begin(), y.end(), patterns_.begin() + i * kNormalHarmonics);
        Eigen::Matrix<double, kNormalHarmonics, 1> v;
        for (std::size_t q = 0; q < kNormalHarmonics; ++q) v[q] = y[q];
        gram += v * v.transpose();
    }
    // Eigen's default rank threshold: a flat patch (every normal the same) leaves only Y_0 and
    // the constant combinations, which the pseudo-inverse solves with the minimum norm.
    Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix<double, 9, 9>> decomposition(gram);
    const Eigen::Matrix<double, 9, 9> inverse = decomposition.pseudoInverse();
    for (std::size_t r = 0; r < kNormalHarmonics; ++r)
        for (std::size_t c = 0; c < kNormalHarmonics; ++c) solve_[r * kNormalHarmonics + c] = inverse(r, c);
}

std::vector<float> HarmonicFit::coefficients(std::span<const float> values, std::size_t C) const {
    const std::size_t n = samples();
    if (C == 0 || values.size() != n * C)
        throw Error("harmonic fit: " + std::to_string(values.size()) + " values for " + std::to_string(n) +
                    " samples of " + std::to_string(C) + " channels");
    // b[q * C + c] = sum_i Y_q(n_i) values[i * C + c], in double over blocks of samples.
    using Sums = std::vector<double>;
    const Sums b = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, n, 4096), Sums(kNormalHarmonics * C, 0.0),
        [&](const tbb::blocked_range<std::size_t>& r, Sums sums) {
            for (std::size_t i = r.begin(); i != r.end(); ++i) {
                const float* y = patterns_.data() + i * kNormalHarmonics;
                const float* v = values.data() + i * C;
                for (std::size_t q = 0; q < kNormalHarmonics; ++q)
                    for (std::size_t c = 0; c < C; ++c) sums[q * C + c] += double(y[q]) * double(v[c]);
            }
            return sums;
        },
        [](Sums a, const Sums& b) {
            for (std::size_t i = 0; i < a.size(); ++i) a[i] += b[i];
            return a;
        });
    std::vector<float> a(kNormalHarmonics * C);
    for (std::size_t q = 0; q < kNormalHarmonics; ++q)
        for (std::size_t c = 0; c < C; ++c) {
            double sum = 0.0;
            for (std::size_t r = 0; r < kNormalHarmonics; ++r) sum += solve_[q * kNormalHarmonics + r] * b[r * C + c];
            a[q * C + c] = float(sum);
        }
    return a;
}

void HarmonicFit::residual(std::span<const float> values, std::size_t C, std::span<const float> a,
                           std::span<float> residual, std::size_t stride) const {
    const std::size_t n = samples();
    if (C == 0 || stride < C || values.size() != n * C || a.size() != kNormalHarmonics * C ||
        residual.size() < (n == 0 ? 0 : (n - 1) * stride + C))
        throw Error("harmonic fit: residual of " + std::to_string(values.size()) + " values (" + std::to_string(C) +
                    " channels, stride " + std::to_string(stride) + ") does not fit " + std::to_string(n) +
                    " samples");
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
            const float* y = patterns_.data() + i * kNormalHarmonics;
            for (std::size_t c = 0; c < C; ++c) {
                float base = 0.0f;
                for (std::size_t q = 0; q < kNormalHarmonics; ++q) base += a[q * C + c] * y[q];
                residual[i * stride + c] = values[i * C + c] - base;
            }
        }
    });
}

}  // namespace opal
