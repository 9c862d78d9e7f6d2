// An Embree 3 scene of the world-space triangle meshes of a render index (hdEmbree keeps
// one Embree scene per index the same way). Two queries: occlusion along a segment (the
// shadow rays of analytic lights, DESIGN.md s.6) and the closest hit (the render pass's
// primary rays, s.7), each one ray at a time, as a stream of unrelated rays, or as
// coherent packets: Embree traverses 8 rays that start close together and point alike
// (neighbouring pixels' primary rays, their shadow rays toward one light) about twice as
// fast together as one by one. Polygons are fanned into triangles: triangle t of a face with
// corners c0..c(n-1) is (c0, c(t+1), c(t+2)).
//
// Build: addMesh() for every mesh, then commit(). Queries are const and thread-safe on a
// committed scene; adding a mesh afterwards needs another commit().
#pragma once

#include "schema/asset/translucent_asset.h"

#include <embree3/rtcore.h>

#include <Imath/ImathBox.h>
#include <Imath/ImathMatrix.h>
#include <Imath/ImathVec.h>

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace opal {

// A ray segment origin + t direction, t in [tNear, tFar].
struct Ray {
    Imath::V3f origin;
    Imath::V3f direction;
    float tNear = 0.0f;
    float tFar = 0.0f;
};

struct RayHit {
    std::uint32_t prim = 0;      // the mesh, numbered in the order added
    std::uint32_t triangle = 0;  // the fanned triangle within that mesh
    float u = 0.0f, v = 0.0f;    // barycentrics: p = (1 - u - v) p0 + u p1 + v p2
    float t = 0.0f;              // ray parameter of the hit
    Imath::V3f geometricNormal;  // (p1 - p0) x (p2 - p0), world space, not normalized
};

class RayScene {
public:
    RayScene();
    ~RayScene();
    RayScene(const RayScene&) = delete;
    RayScene& operator=(const RayScene&) = delete;

    // Adds a mesh with points mapped to world space by objectToWorld (row vectors, as USD
    // and Imath: p_world = p_object * M). Returns its prim number. Throws opal::Error on
    // an index out of range or a face with fewer than three corners.
    std::uint32_t addMesh(const RenderMesh& mesh, const Imath::M44d& objectToWorld);
    // Builds the acceleration structure. Throws opal::Error when Embree reports an error.
    void commit();

    std::uint32_t meshCount() const { return std::uint32_t(meshes_.size()); }
    // The render-mesh vertices (p0, p1, p2) and the polygon of a hit triangle.
    std::array<std::uint32_t, 3> triangleVertices(std::uint32_t prim, std::uint32_t triangle) const;
    // Every fanned triangle's vertices of one mesh (3 per triangle), unchecked per triangle:
    // for the renderer's per-pixel loop. Throws opal::Error for a prim out of range.
    std::span<const std::uint32_t> triangles(std::uint32_t prim) const;
    std::uint32_t triangleFace(std::uint32_t prim, std::uint32_t triangle) const;
    // The diagonal of the world bounding box of every mesh: the scale for ray offsets.
    float extent() const { return extent_; }
    // The world bounding box of every mesh.
    const Imath::Box3f& bounds() const { return bounds_; }

    bool occluded(const Ray& ray) const;
    // blocked[i] = 1 when rays[i] hits something, else 0 (Embree's stream API).
    void occluded(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const;
    std::optional<RayHit> intersect(const Ray& ray) const;

    // Packets: the same answers as the one-ray queries, for rays traced kPacketSize at a time
    // (rtcOccluded16 / rtcIntersect16 over consecutive rays; any count). Throws opal::Error
    // when the spans differ in size. Embree takes packets of 4, 8 or 16 on every ISA; 16
    // suits its AVX-512 kernels (the 720p benchmark frame on this AVX-512 machine: min 48
    // -> 44 ms against 8-ray packets).
    static constexpr std::size_t kPacketSize = 16;
    void occludedCoherent(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const;
    void intersectCoherent(std::span<const Ray> rays, std::span<std::optional<RayHit>> hits) const;

private:
    struct Mesh {
        std::vector<std::uint32_t> triangles;  // 3 vertex indices each
        std::vector<std::uint32_t> faceOfTriangle;
    };
    void requireCommitted(const char* query) const;
    void requireSizes(std::size_t rays, std::size_t results) const;

    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    std::vector<Mesh> meshes_;
    float extent_ = 0.0f;
    Imath::Box3f bounds_;
    bool committed_ = false;
};

}  // namespace opal
