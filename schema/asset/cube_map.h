// The cube-map layout shared by the bake (environment visibility) and the delegate (the
// environment light): 6 faces of size x size texels, faces in OpenGL order +X, -X, +Y,
// -Y, +Z, -Z, each face row-major with v down. Directions are in the asset's object space
// (right-handed). A cube-map signal is stored face after face: index = face*size^2 +
// v*size + u, which is also a ChartLayout of 6 charts, so the Haar transform per chart
// applies as is.
#pragma once

#include "schema/wavelet/chart_layout.h"

#include <Imath/ImathVec.h>

#include <cstdint>

namespace opal {

struct CubeMapTexel {
    std::uint32_t face = 0, u = 0, v = 0;
};

// Where a direction meets the cube: its face and face coordinates (s, t) in [-1, 1]^2,
// the inverse of CubeMapLayout::faceDirection. A zero or NaN direction gives face 0, (0, 0).
struct CubeFacePoint {
    std::uint32_t face = 0;
    float s = 0.0f, t = 0.0f;
};

class CubeMapLayout {
public:
    static constexpr std::uint32_t kMaxFaceSize = 1024;
    explicit CubeMapLayout(std::uint32_t faceSize);  // a power of two up to kMaxFaceSize

    std::uint32_t faceSize() const { return size_; }
    std::uint32_t texels() const { return 6 * size_ * size_; }
    ChartLayout charts() const;

    std::uint32_t index(const CubeMapTexel& t) const { return (t.face * size_ + t.v) * size_ + t.u; }
    CubeMapTexel texel(std::uint32_t index) const;

    // Unit direction through the centre of a texel, or through face coordinates (s, t) in
    // [-1, 1]^2 on a face.
    Imath::V3f direction(std::uint32_t index) const;
    static Imath::V3f faceDirection(std::uint32_t face, float s, float t);
    static CubeFacePoint facePoint(const Imath::V3f& direction);
    // The texel a direction falls in.
    std::uint32_t lookup(const Imath::V3f& direction) const;
    // The solid angle a texel subtends (steradians); they sum to 4 pi.
    double solidAngle(std::uint32_t index) const;

private:
    std::uint32_t size_;
};

}  // namespace opal
