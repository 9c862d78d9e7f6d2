// The clamped-cosine integral of each texel of a cube map, W_i(n) = integral over texel i
// of max(0, n.w) dw, so that the irradiance of a cube map of radiance L is
// E(n) = sum_i L_i W_i(n) exactly for radiance constant over each texel. A texel wholly
// above the horizon of n (n.w_c >= sin of the angle from its centre w_c to its farthest
// corner) gives n.V_i with V_i = integral of w dw over the texel (exact: the cosine is
// linear there); one wholly below gives 0; one the horizon crosses is summed over 4 x 4
// sub-texels (the cube map of 4 times the face size).
#pragma once

#include "schema/asset/cube_map.h"

#include <Imath/ImathVec.h>

#include <vector>

namespace opal {

class CubeMapCosineIntegral {
public:
    explicit CubeMapCosineIntegral(const CubeMapLayout& layout);
    double weight(std::uint32_t texel, const Imath::V3d& normal) const;

private:
    static constexpr std::uint32_t kSplit = 4;
    std::vector<Imath::V3d> centres_, vectorSolidAngles_;
    std::vector<double> sinHalfAngles_;
    std::vector<Imath::V3d> subDirections_;  // kSplit^2 per texel
    std::vector<double> subSolidAngles_;
};

}  // namespace opal
