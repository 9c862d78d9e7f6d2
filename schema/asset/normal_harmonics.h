// The smooth part of the light, transferred exactly (docs/ARCHITECTURE.md#harmonic-transfer).
//
// Light with contrast is what the compressed transfer renders worst: its error is set by
// the brightest light, so a dimly lit side carries the same absolute error on a small
// signal. Most of a dome's contrast, and much of any light's, is a smooth function of the
// surface normal, which the nine functions Y_q(n) below span (the real spherical harmonics
// of order <= 2, without their constant factors: Ramamoorthi and Hanrahan 2001 showed that
// they hold all but a few percent of any distant light's irradiance on a convex surface).
// A near light also falls off with distance across the object, which the normal cannot
// tell; the 36 functions f_q = Y_h(n) p_b(x), p = (1, x', y', z') the position in the
// set's frame (HarmonicSet), span that too: on a 34 mm torus under a point light 56 mm
// away they leave 10% of E's norm, the nine 34%. The bake stores each T_k f_q exactly;
// at run time each moment and channel of E is split by least squares into
// sum_q a_q f_q(x_i, n_i) and a residual, and only the residual goes through the
// compressed matrices:
//
//     T_k E = T_k R + sum_q a_q (T_k f_q),    R = E - sum_q a_q f_q
//
// The split is exact for any a (it is linear), so a fit that is poor somewhere costs
// accuracy, never correctness.
#pragma once

#include "schema/asset/translucent_asset.h"

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace opal {

inline constexpr std::size_t kNormalHarmonics = 9;
inline constexpr std::size_t kPositionFactors = 4;                                 // 1, x', y', z'
inline constexpr std::size_t kMaxHarmonics = kNormalHarmonics * kPositionFactors;  // 36

// Y_q(n) for q < 9: 1, x, y, z, xy, yz, 3z^2 - 1, xz, x^2 - y^2 of n = (x, y, z). Stored
// transfers were baked with exactly these: they are frozen.
std::array<float, kNormalHarmonics> normalHarmonics(const Imath::V3f& n);

// True for the counts a HarmonicSet may have: 9 and 36.
bool isHarmonicCount(std::uint64_t count);

// f_q(x, n) of one sample, q < set.count: out[b * 9 + h] = Y_h(n) p_b(x) with
// p = (1, x', y', z'), x' = (x - centre) inverseScale; the first nine are Y_h(n). Frozen as
// normalHarmonics. Throws opal::Error unless out.size() == set.count and the count is 9 or 36.
void harmonicValues(const HarmonicSet& set, const SurfaceSample& sample, std::span<float> out);

// The set the bake uses for these samples: 36 functions, the frame their bounding box's
// centre and half its largest extent (inverseScale 1 for a single point).
HarmonicSet harmonicSetFor(std::span<const SurfaceSample> samples);

// The least-squares split of per-sample values onto the set's functions of the samples.
class HarmonicFit {
public:
    // Throws opal::Error for a count that is not 9 or 36.
    HarmonicFit(std::span<const SurfaceSample> samples, const HarmonicSet& set);

    std::size_t count() const { return count_; }
    std::size_t samples() const { return count_ == 0 ? 0 : patterns_.size() / count_; }

    // a[q * C + c] minimizing sum_i (values[i * C + c] - sum_q a[q * C + c] f_q(x_i, n_i))^2,
    // for values of samples() x C (interleaved). The minimum-norm solution where the
    // samples do not tell the functions apart (a flat patch: every n the same). Throws
    // opal::Error for a size mismatch.
    std::vector<float> coefficients(std::span<const float> values, std::size_t C) const;

    // residual[i * stride + c] = values[i * C + c] - sum_q a[q * C + c] f_q(x_i, n_i), c < C.
    void residual(std::span<const float> values, std::size_t C, std::span<const float> a, std::span<float> residual,
                  std::size_t stride) const;

    // f_q(x_i, n_i) as stored: patterns()[i * count() + q].
    std::span<const float> patterns() const { return patterns_; }

private:
    std::size_t count_ = 0;
    std::vector<float> patterns_;  // samples x count
    std::vector<double> solve_;    // count x count: the Gram matrix's pseudo-inverse
};

}  // namespace opal
