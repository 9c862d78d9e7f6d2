// The clamped-cosine integral of each texel of a cube map, W_i(n) = integral over texel i
// of max(0, n.w) dw, so that the irradiance of a cube map of radiance L is
// E(n) = sum_i L_i W_i(n), exact for radiance constant over each texel. A texel is a
// spherical quadrilateral with great-circle edges (straight lines on its face), and so is
// its part above the horizon of n (the texel clipped by the plane n.w = 0, a great
// circle): W_i(n) = n . V, with V = integral of w dw over that part, from its corners by
// Arvo's formula for spherical polygons (1995): V = 1/2 sum over edges (a, b) of
// angle(a, b) (a x b) / |a x b|. Texels wholly above the horizon use V precomputed;
// those wholly below give 0.
#pragma once

#include "schema/asset/cube_map.h"

#include <Imath/ImathVec.h>

#include <algorithm>
#include <array>
#include <span>
#include <vector>

namespace opal {

class CubeMapCosineIntegral {
public:
    explicit CubeMapCosineIntegral(const CubeMapLayout& layout);
    // Inline: per-sample loops weigh a few hundred texels, most wholly above or below the
    // horizon; only a texel the horizon crosses is clipped (out of line).
    double weight(std::uint32_t texel, const Imath::V3d& normal) const {
        const Texel& t = texels_[texel];
        const double c = normal.dot(t.centre);
        if (c >= t.sinHalfAngle) return std::max(0.0, normal.dot(t.vectorSolidAngle));
        if (c <= -t.sinHalfAngle) return 0.0;
        return clippedWeight(texel, normal);
    }

    // Integral of w dw over a spherical polygon with great-circle edges between its unit
    // corners, for corners counter-clockwise seen from outside the sphere (negated for
    // the other winding).
    static Imath::V3d vectorSolidAngle(std::span<const Imath::V3d> corners);

private:
    // What the fast path reads, together (one texel's data in one place).
    struct Texel {
        Imath::V3d centre, vectorSolidAngle;
        double sinHalfAngle = 0.0;
    };
    double clippedWeight(std::uint32_t texel, const Imath::V3d& normal) const;

    std::vector<std::array<Imath::V3d, 4>> corners_;  // wound so that V points into the texel
    std::vector<Texel> texels_;
};

}  // namespace opal
