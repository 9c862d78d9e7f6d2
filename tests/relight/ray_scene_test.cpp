#include "raytrace/ray_scene.h"

#include "schema/error.h"
#include "tests/relight/translation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

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

using test::translation;

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

// Rays Embree's assertions would abort on (Debian builds Embree with them): each becomes the
// empty segment, which every query form traces without hitting anything.
TEST(Ray, WhatEmbreeWouldRejectBecomesTheEmptySegment) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const Imath::V3f o(0.5f, 0.0f, 0.5f), up(0, 1, 0);
    const std::vector<Ray> bad = {
        Ray({nan, 0, 0}, up, 0, 2),        Ray(o, {0, nan, 0}, 0, 2),      Ray({3.4e38f, 0, 0}, up, 0, 2),
        Ray(o, {0, 2e18f, 0}, 0, 2),       Ray({inf, 0, 0}, up, 0, 2),     Ray(o, {0, 0, 0}, 0, 2),
        Ray(o, up, nan, 2),                Ray(o, up, 0, nan),             Ray(o, up, -1, 2),
        Ray(o, up, 3, 2),
    };
    for (const Ray& r : bad) {
        EXPECT_TRUE(r.empty());
        EXPECT_TRUE(std::isfinite(r.origin().x) && std::isfinite(r.direction().y) && r.tNear() >= 0.0f);
    }
    EXPECT_FALSE(Ray(o, up, 0, inf).empty());  // an unbounded segment is fine
    EXPECT_FALSE(Ray(o, up, 0, 0).empty());    // so is a point

    RayScene scene;
    scene.addMesh(unitQuad(), translation(0, 1, 0));
    scene.commit();
    std::vector<std::uint8_t> blocked(bad.size(), 7);
    scene.occluded(bad, blocked);
    for (std::uint8_t b : blocked) EXPECT_EQ(b, 0);
    scene.occludedCoherent(bad, blocked);
    for (std::uint8_t b : blocked) EXPECT_EQ(b, 0);
    std::vector<std::optional<RayHit>> hits(bad.size());
    scene.intersectCoherent(bad, hits);
    for (std::size_t i = 0; i < bad.size(); ++i) {
        EXPECT_FALSE(hits[i]) << i;
        EXPECT_FALSE(scene.intersect(bad[i])) << i;
        EXPECT_FALSE(scene.occluded(bad[i])) << i;
    }
}

// 1e30 over the stack below the caller's frame, where a callee's locals will lie: as a
// stale packet slot it reads as tnear = tfar = 1e30 (a segment Embree's stream filter
// traces) with an origin beyond Embree's 1.8e18 limit.
[[gnu::noinline]] void poisonStack() {
    volatile float junk[16384];
    for (volatile float& f : junk) f = 1e30f;
}

// The main job's abort, made deterministic: a packet query with fewer rays than a packet
// holds, on a stack full of garbage. On processors without native 16-wide Embree kernels (AVX2,
// as on this project's machines) Embree ignores the valid mask and traces every slot whose
// tnear <= tfar, so unused slots must hold the empty segment (ray_scene.cpp).
TEST(RayScene, PartialPacketsNeverHandEmbreeStaleSlots) {
    RayScene scene;
    scene.addMesh(unitQuad(), translation(0, 1, 0));
    scene.commit();
    for (std::size_t count = 1; count < RayScene::kPacketSize; ++count) {
        const std::vector<Ray> rays(count, Ray({0.5f, 0.0f, 0.5f}, {0, 1, 0}, 0.0f, 2.0f));
        std::vector<std::uint8_t> blocked(count);
        poisonStack();
        scene.occludedCoherent(rays, blocked);
        for (std::uint8_t b : blocked) EXPECT_EQ(b, 1);
        std::vector<std::optional<RayHit>> hits(count);
        poisonStack();
        scene.intersectCoherent(rays, hits);
        for (const std::optional<RayHit>& hit : hits) EXPECT_TRUE(hit && std::abs(hit->t - 1.0f) < 1e-6f);
    }
}

TEST(RayScene, RefusesPointsOutsideTheRangeNamingTheFirst) {
    for (const float bad : {3.4e38f, std::numeric_limits<float>::quiet_NaN(), 2e12f}) {
        RayScene scene;
        RenderMesh mesh = unitQuad();
        mesh.points[2].y = bad;
        try {
            scene.addMesh(mesh, Imath::M44d());
            ADD_FAILURE() << "accepted a point at " << bad;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("point 2 lies at"), std::string::npos) << e.what();
        }
    }
    // A transform can carry a good mesh out of range too.
    Imath::M44d huge;
    huge.setScale(1e13);
    RayScene scene;
    EXPECT_THROW(scene.addMesh(unitQuad(), huge), Error);
}

}  // namespace
}  // namespace opal
