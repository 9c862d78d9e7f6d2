// The cube-map layout's direction <-> texel maps: facePoint inverts faceDirection, and
// every texel's centre direction looks up that texel; degenerate directions give a texel.
#include "schema/asset/cube_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace opal {
namespace {

TEST(CubeMap, FacePointInvertsFaceDirection) {
    for (std::uint32_t face = 0; face < 6; ++face)
        for (float s = -0.95f; s < 1.0f; s += 0.1f)
            for (float t = -0.95f; t < 1.0f; t += 0.1f) {
                const CubeFacePoint p = CubeMapLayout::facePoint(CubeMapLayout::faceDirection(face, s, t) * 3.0f);
                EXPECT_EQ(p.face, face);
                EXPECT_NEAR(p.s, s, 1e-5f);
                EXPECT_NEAR(p.t, t, 1e-5f);
            }
}

TEST(CubeMap, TexelCentresLookUpTheirTexel) {
    for (std::uint32_t size : {1u, 2u, 16u, 32u}) {
        const CubeMapLayout layout(size);
        for (std::uint32_t i = 0; i < layout.texels(); ++i) EXPECT_EQ(layout.lookup(layout.direction(i)), i) << size;
    }
}

TEST(CubeMap, DegenerateDirectionsGiveATexel) {
    const CubeMapLayout layout(8);
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    for (const Imath::V3f& d : {Imath::V3f(0.0f), Imath::V3f(nan, 0, 0), Imath::V3f(inf, inf, 0), Imath::V3f(1, nan, 0)})
        EXPECT_LT(layout.lookup(d), layout.texels());
}

}  // namespace
}  // namespace opal
