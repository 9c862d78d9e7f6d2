// The clamped-cosine weights of cube-map texels: over the whole sphere they integrate
// max(0, n.w) to pi for any normal (exactly: texels the horizon crosses are clipped
// exactly), and over a cap of texels around n to about the cap's projected solid angle
// pi sin^2(theta).
#include "schema/asset/cube_map_cosine.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace opal {
namespace {

const Imath::V3d kNormals[] = {{0, 1, 0}, {1, 0, 0}, {0.6, 0.0, -0.8}, {0.48, 0.6, 0.64}};

TEST(CubeMapCosine, WeightsIntegrateTheClampedCosineToPi) {
    for (std::uint32_t size : {1u, 4u, 32u, 128u}) {
        const CubeMapLayout layout(size);
        const CubeMapCosineIntegral cosine(layout);
        for (const Imath::V3d& n : kNormals) {
            double sum = 0.0;
            for (std::uint32_t i = 0; i < layout.texels(); ++i) sum += cosine.weight(i, n);
            EXPECT_NEAR(sum, std::numbers::pi, 1e-6) << size << " " << n;
        }
    }
}

// The texels whose centres lie within 60 degrees of n: their weights sum to what their
// own region projects, close to pi sin^2(60) = 3 pi / 4 up to the staircase of texels.
TEST(CubeMapCosine, ACapOfTexelsProjectsItsArea) {
    const CubeMapLayout layout(64);
    const CubeMapCosineIntegral cosine(layout);
    for (const Imath::V3d& n : kNormals) {
        double sum = 0.0;
        for (std::uint32_t i = 0; i < layout.texels(); ++i)
            if (n.dot(Imath::V3d(layout.direction(i))) >= 0.5) sum += cosine.weight(i, n);
        EXPECT_NEAR(sum, 0.75 * std::numbers::pi, 0.01) << n;
    }
}

// A single spherical triangle: the octant x, y, z >= 0 has vector solid angle
// (pi/4, pi/4, pi/4) (each axis' cosine integrates to pi/4 over it).
TEST(CubeMapCosine, VectorSolidAngleOfTheOctant) {
    const Imath::V3d corners[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const Imath::V3d v = CubeMapCosineIntegral::vectorSolidAngle(corners);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(v[i], std::numbers::pi / 4, 1e-12);
}

}  // namespace
}  // namespace opal
