#include "delegate/ray_scene.h"

#include "schema/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace opal {
namespace {

// A unit quad in the plane y = 0 over [0, 1] x [0, 1], one polygon.
RenderMesh unitQuad() {
    RenderMesh mesh;
    mesh.points = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
    mesh.faceVertexCounts = {4};
    mesh.faceVertexIndices = {0, 1, 2, 3};
    return mesh;
}

Imath::M44d translation(double x, double y, double z) {
    Imath::M44d m;
    m.setTranslation(Imath::V3d(x, y, z));
    return m;
}

TEST(RayScene, ClosestHitGivesPrimTriangleBarycentricsAndDistance) {
    RayScene scene;
    EXPECT_EQ(scene.addMesh(unitQuad(), translation(0, 1, 0)), 0u);  // at y = 1
    EXPECT_EQ(scene.addMesh(unitQuad(), translation(0, 3, 0)), 1u);  // at y = 3
    scene.commit();

    const Imath::V3f origin(0.7f, 0.0f, 0.2f);
    const std::optional<RayHit> hit = scene.intersect({origin, {0, 1, 0}, 0.0f, 100.0f});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->prim, 0u);
    EXPECT_NEAR(hit->t, 1.0f, 1e-6f);
    // The barycentrics reproduce the hit point from the triangle's vertices.
    const std::array<std::uint32_t, 3> v = scene.triangleVertices(hit->prim, hit->triangle);
    const RenderMesh quad = unitQuad();
    const Imath::V3f p = quad.points[v[0]] * (1 - hit->u - hit->v) + quad.points[v[1]] * hit->u + quad.points[v[2]] * hit->v;
    EXPECT_NEAR(p.x, 0.7f, 1e-5f);
    EXPECT_NEAR(p.z, 0.2f, 1e-5f);
    EXPECT_EQ(scene.triangleFace(hit->prim, hit->triangle), 0u);
    EXPECT_NEAR(std::abs(hit->geometricNormal.normalized().y), 1.0f, 1e-6f);

    // Starting past the first quad, the second is hit.
    const std::optional<RayHit> second = scene.intersect({origin, {0, 1, 0}, 1.5f, 100.0f});
    ASSERT_TRUE(second);
    EXPECT_EQ(second->prim, 1u);
    EXPECT_NEAR(second->t, 3.0f, 1e-6f);
    EXPECT_FALSE(scene.intersect({origin, {0, -1, 0}, 0.0f, 100.0f}));
    EXPECT_NEAR(scene.extent(), std::sqrt(1.0f + 4.0f + 1.0f), 1e-5f);  // box [0,1] x [1,3] x [0,1]
}

TEST(RayScene, OcclusionRespectsTheSegment) {
    RayScene scene;
    scene.addMesh(unitQuad(), translation(0, 1, 0));
    scene.commit();
    const Imath::V3f origin(0.5f, 0.0f, 0.5f);
    EXPECT_TRUE(scene.occluded(Ray{origin, {0, 1, 0}, 0.0f, 2.0f}));
    EXPECT_FALSE(scene.occluded(Ray{origin, {0, 1, 0}, 0.0f, 0.9f}));  // stops short
    EXPECT_FALSE(scene.occluded(Ray{{1.5f, 0, 0.5f}, {0, 1, 0}, 0.0f, 2.0f}));  // misses

    // The stream form agrees ray by ray.
    std::vector<Ray> rays;
    for (int i = 0; i < 200; ++i)
        rays.push_back({{-0.5f + 0.01f * float(i), 0.0f, 0.5f}, {0, 1, 0}, 0.0f,
                        i % 3 == 0 ? 0.5f : std::numeric_limits<float>::infinity()});
    std::vector<std::uint8_t> blocked(rays.size());
    scene.occluded(rays, blocked);
    for (std::size_t i = 0; i < rays.size(); ++i) EXPECT_EQ(bool(blocked[i]), scene.occluded(rays[i])) << i;
}

TEST(RayScene, RejectsBadMeshesAndUncommittedQueries) {
    RayScene scene;
    RenderMesh bad = unitQuad();
    bad.faceVertexIndices[2] = 9;
    EXPECT_THROW(scene.addMesh(bad, Imath::M44d()), Error);
    scene.addMesh(unitQuad(), Imath::M44d());
    EXPECT_THROW(scene.occluded(Ray{{0, -1, 0}, {0, 1, 0}, 0, 2}), Error);
}

}  // namespace
}  // namespace opal
