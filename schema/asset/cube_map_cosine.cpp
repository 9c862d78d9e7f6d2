#include "schema/asset/cube_map_cosine.h"

#include <algorithm>
#include <cmath>

namespace opal {

Imath::V3d CubeMapCosineIntegral::vectorSolidAngle(std::span<const Imath::V3d> corners) {
    Imath::V3d sum(0.0);
    for (std::size_t k = 0; k < corners.size(); ++k) {
        const Imath::V3d& a = corners[k];
        const Imath::V3d& b = corners[(k + 1) % corners.size()];
        const Imath::V3d normal = a.cross(b);
        const double sine = normal.length();
        if (!(sine > 0.0)) continue;  // a repeated corner
        sum += normal * (0.5 * std::atan2(sine, a.dot(b)) / sine);
    }
    return sum;
}

CubeMapCosineIntegral::CubeMapCosineIntegral(const CubeMapLayout& layout) {
    const std::uint32_t size = layout.faceSize();
    for (std::uint32_t i = 0; i < layout.texels(); ++i) {
        const CubeMapTexel t = layout.texel(i);
        const Imath::V3d centre = Imath::V3d(layout.direction(i)).normalized();
        std::array<Imath::V3d, 4> corners;
        double cosHalf = 1.0;
        for (int k = 0; k < 4; ++k) {  // around the texel's square on its face
            const std::uint32_t du = k == 1 || k == 2, dv = k >= 2;
            const float s = 2.0f * float(t.u + du) / float(size) - 1.0f;
            const float v = 2.0f * float(t.v + dv) / float(size) - 1.0f;
            corners[k] = Imath::V3d(CubeMapLayout::faceDirection(t.face, s, v)).normalized();
            cosHalf = std::min(cosHalf, centre.dot(corners[k]));
        }
        Imath::V3d vector = vectorSolidAngle(corners);
        if (vector.dot(centre) < 0.0) {  // the face's (s, t) are mirrored: wind the other way
            std::reverse(corners.begin(), corners.end());
            vector = -vector;
        }
        corners_.push_back(corners);
        texels_.push_back({centre, vector, std::sqrt(std::max(0.0, 1.0 - cosHalf * cosHalf))});
    }
}

double CubeMapCosineIntegral::clippedWeight(std::uint32_t texel, const Imath::V3d& n) const {
    // Sutherland-Hodgman against n.w >= 0; the crossing of an edge with the plane, scaled
    // onto the sphere, lies on both great circles.
    const std::array<Imath::V3d, 4>& corners = corners_[texel];
    Imath::V3d clipped[8];
    std::size_t count = 0;
    for (std::size_t k = 0; k < 4; ++k) {
        const Imath::V3d& a = corners[k];
        const Imath::V3d& b = corners[(k + 1) % 4];
        const double da = n.dot(a), db = n.dot(b);
        if (da >= 0.0) clipped[count++] = a;
        if ((da >= 0.0) != (db >= 0.0)) clipped[count++] = (a * db - b * da).normalized() * (db > da ? 1.0 : -1.0);
    }
    if (count < 3) return 0.0;
    return std::max(0.0, n.dot(vectorSolidAngle({clipped, count})));
}

}  // namespace opal
