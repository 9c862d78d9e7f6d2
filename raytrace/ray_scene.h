// An Embree 3 scene of world-space triangle meshes: the render index's meshes (hdEmbree
// keeps one Embree scene per index the same way) and the bake's render mesh. Two queries:
// occlusion along a segment (shadow rays of lights, the bake's visibility) and the closest
// hit (primary rays), each one ray at a time, as a stream of unrelated rays, or as
// coherent packets: Embree traverses 8 rays that start close together and point alike
// (neighbouring pixels' primary rays, their shadow rays toward one light) about twice as
// fast together as one by one. Polygons are fanned into triangles: triangle t of a face with
// corners c0..c(n-1) is (c0, c(t+1), c(t+2)).
//
// Build: addMesh() for every mesh, then commit(). Queries are const and thread-safe on a
// committed scene; adding a mesh afterwards needs another commit().
//
// Every ray is a Ray (ray.h), valid for Embree by construction; every world-space point is
// finite and within kMaxWorldCoordinate (addMesh refuses others), so that points, offsets
// along normals and ray parameters stay far inside Embree's range. A hit on a triangle
// whose geometric normal is zero or not finite (a degenerate triangle, reachable by camera
// rays) counts as a miss: nothing can be shaded there.
#pragma once

#include "raytrace/ray.h"
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

struct RayHit {
    std::uint32_t prim = 0;      // the mesh, numbered in the order added
    std::uint32_t triangle = 0;  // the fanned triangle within that mesh
    float u = 0.0f, v = 0.0f;    // barycentrics: p = (1 - u - v) p0 + u p1 + v p2
    float t = 0.0f;              // ray parameter of the hit
    Imath::V3f geometricNormal;  // (p1 - p0) x (p2 - p0), world space, not normalized
};

class RayScene {
public:
    // World coordinates above this magnitude are refused: a millionth of Embree's limit,
    // so that a scene's extent, ray offsets and far ray parameters stay finite and in range.
    static constexpr double kMaxWorldCoordinate = 1e12;

    // Bvh build quality: Medium for the render index (rebuilt on edits), High for a bake.
    enum class BuildQuality { Medium, High };
    explicit RayScene(BuildQuality quality = BuildQuality::Medium);
    ~RayScene();
    RayScene(const RayScene&) = delete;
    RayScene& operator=(const RayScene&) = delete;

    // Adds a mesh with points mapped to world space by objectToWorld (row vectors, as USD
    // and Imath: p_world = p_object * M). Returns its prim number. Throws opal::Error on
    // an index out of range, a face with fewer than three corners, or a world point that is
    // not finite or exceeds kMaxWorldCoordinate (naming the first such point's index).
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
