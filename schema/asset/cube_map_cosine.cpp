#include "schema/asset/cube_map_cosine.h"

#include <algorithm>
#include <cmath>

namespace opal {

CubeMapCosineIntegral::CubeMapCosineIntegral(const CubeMapLayout& layout) {
    const std::uint32_t size = layout.faceSize();
    const CubeMapLayout fine(std::min(size * kSplit, CubeMapLayout::kMaxFaceSize));
    const std::uint32_t split = fine.faceSize() / size;
    for (std::uint32_t i = 0; i < layout.texels(); ++i) {
        const CubeMapTexel t = layout.texel(i);
        const Imath::V3d centre(layout.direction(i));
        double cosHalf = 1.0;
        for (int corner = 0; corner < 4; ++corner) {
            const float s = 2.0f * float(t.u + (corner & 1)) / float(size) - 1.0f;
            const float v = 2.0f * float(t.v + (corner >> 1)) / float(size) - 1.0f;
            cosHalf = std::min(cosHalf, centre.dot(Imath::V3d(CubeMapLayout::faceDirection(t.face, s, v))));
        }
        Imath::V3d vector(0.0);
        for (std::uint32_t a = 0; a < split; ++a)
            for (std::uint32_t b = 0; b < split; ++b) {
                const std::uint32_t f = fine.index({t.face, t.u * split + b, t.v * split + a});
                subDirections_.emplace_back(fine.direction(f));
                subSolidAngles_.push_back(fine.solidAngle(f));
                vector += subDirections_.back() * subSolidAngles_.back();
            }
        centres_.push_back(centre);
        vectorSolidAngles_.push_back(vector);
        sinHalfAngles_.push_back(std::sqrt(std::max(0.0, 1.0 - cosHalf * cosHalf)));
    }
}

double CubeMapCosineIntegral::weight(std::uint32_t texel, const Imath::V3d& n) const {
    const double c = n.dot(centres_[texel]);
    if (c >= sinHalfAngles_[texel]) return std::max(0.0, n.dot(vectorSolidAngles_[texel]));
    if (c <= -sinHalfAngles_[texel]) return 0.0;
    const std::size_t count = subSolidAngles_.size() / centres_.size(), first = texel * count;
    double sum = 0.0;
    for (std::size_t k = first; k < first + count; ++k) sum += std::max(0.0, n.dot(subDirections_[k])) * subSolidAngles_[k];
    return sum;
}

}  // namespace opal
