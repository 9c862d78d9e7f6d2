// The smooth part of the light, transferred exactly (docs/ARCHITECTURE.md#harmonic-transfer).
//
// Light with contrast is what the compressed transfer renders worst: its error is set by
// the brightest light, so a dimly lit side carries the same absolute error on a small
// signal. Most of a dome's contrast, and much of any light's, is a smooth function of the
// surface normal, which the nine functions Y_q(n) below span (the real spherical harmonics
// of order <= 2, without their constant factors: Ramamoorthi and Hanrahan 2001 showed that
// they hold all but a few percent of any distant light's irradiance on a convex surface).
// The bake stores each T_k Y_q exactly; at run time each moment and channel of E is split
// by least squares into sum_q a_q Y_q(n_i) and a residual, and only the residual goes
// through the compressed matrices:
//
//     T_k E = T_k R + sum_q a_q (T_k Y_q),    R = E - sum_q a_q Y_q
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

// Y_q(n) for q < 9: 1, x, y, z, xy, yz, 3z^2 - 1, xz, x^2 - y^2 of n = (x, y, z). Stored
// transfers were baked with exactly these: they are frozen.
std::array<float, kNormalHarmonics> normalHarmonics(const Imath::V3f& n);

// The least-squares split of per-sample values onto Y_q(n_i) of the samples' normals.
class HarmonicFit {
public:
    explicit HarmonicFit(std::span<const SurfaceSample> samples);

    std::size_t samples() const { return patterns_.size() / kNormalHarmonics; }

    // a[q * C + c] minimizing sum_i (values[i * C + c] - sum_q a[q * C + c] Y_q(n_i))^2, for
    // values of samples() x C (interleaved). The minimum-norm solution where the normals
    // do not tell the nine apart (a flat patch: every n the same). Throws opal::Error for
    // a size mismatch.
    std::vector<float> coefficients(std::span<const float> values, std::size_t C) const;

    // residual[i * stride + c] = values[i * C + c] - sum_q a[q * C + c] Y_q(n_i), c < C.
    void residual(std::span<const float> values, std::size_t C, std::span<const float> a, std::span<float> residual,
                  std::size_t stride) const;

    // Y_q(n_i) as stored: patterns()[i * 9 + q].
    std::span<const float> patterns() const { return patterns_; }

private:
    std::vector<float> patterns_;                                  // samples x 9
    std::array<double, kNormalHarmonics * kNormalHarmonics> solve_;  // the Gram matrix's pseudo-inverse
};

}  // namespace opal
