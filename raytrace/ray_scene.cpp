#include "raytrace/ray_scene.h"

#include "raytrace/embree_device_config.h"
#include "schema/asset/fan_triangulation.h"
#include "schema/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace opal {

namespace {

[[noreturn]] void embreeFailure(RTCDevice device, const std::string& what) {
    throw Error("Embree: " + what + " failed (error " + std::to_string(int(rtcGetDeviceError(device))) + ")");
}

RTCRay toEmbree(const Ray& r) {
    RTCRay ray{};
    ray.org_x = r.origin().x;
    ray.org_y = r.origin().y;
    ray.org_z = r.origin().z;
    ray.dir_x = r.direction().x;
    ray.dir_y = r.direction().y;
    ray.dir_z = r.direction().z;
    ray.tnear = r.tNear();
    ray.tfar = r.tFar();
    ray.mask = std::numeric_limits<unsigned>::max();
    return ray;
}

// Ray `slot` of an Embree packet (RTCRay16 or the ray of an RTCRayHit16).
void setPacketRay(RTCRay16& packet, std::size_t slot, const Ray& r) {
    packet.org_x[slot] = r.origin().x;
    packet.org_y[slot] = r.origin().y;
    packet.org_z[slot] = r.origin().z;
    packet.dir_x[slot] = r.direction().x;
    packet.dir_y[slot] = r.direction().y;
    packet.dir_z[slot] = r.direction().z;
    packet.tnear[slot] = r.tNear();
    packet.tfar[slot] = r.tFar();
    packet.time[slot] = 0.0f;
    packet.mask[slot] = std::numeric_limits<unsigned>::max();
    packet.id[slot] = 0;
    packet.flags[slot] = 0;
}

// Slots [count, kPacketSize) of a packet: the empty segment. Embree ignores the valid mask
// where the processor has no native 16-wide kernels (an AVX2 machine): rtcOccluded16 and
// rtcIntersect16 then go through its ray-stream filter, which takes every slot with
// tnear <= tfar as a ray. A slot left as it was (stale rays, or uninitialized stack holding
// NaN) was traced there, and Embree's ray.valid() assertion aborted the process: the
// main job's occasional "Aborted" on such machines.
void clearUnusedSlots(RTCRay16& packet, std::size_t count) {
    for (std::size_t i = count; i < RayScene::kPacketSize; ++i) setPacketRay(packet, i, Ray());
}

// Embree's packet valid mask: -1 for the first `count` slots, 0 for the rest.
struct alignas(64) PacketMask {
    int valid[RayScene::kPacketSize];
    explicit PacketMask(std::size_t count) {
        for (std::size_t i = 0; i < RayScene::kPacketSize; ++i) valid[i] = i < count ? -1 : 0;
    }
};

RTCIntersectContext coherentContext() {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    return context;
}

// A hit's geometric normal, or nothing when it is zero or not finite (a degenerate
// triangle): such a hit is a miss, since no surface orientation can be shaded there.
bool shadeableNormal(float x, float y, float z) {
    const float m = std::max({std::abs(x), std::abs(y), std::abs(z)});
    return m > 0.0f && m <= std::numeric_limits<float>::max();
}

// Fans every polygon (schema/asset/fan_triangulation.h), checking indices against the
// point count first.
void fanTriangles(const RenderMesh& mesh, std::vector<std::uint32_t>& triangles,
                  std::vector<std::uint32_t>& faceOfTriangle) {
    std::size_t corner = 0;
    for (std::size_t face = 0; face < mesh.faceVertexCounts.size(); ++face) {
        const std::int32_t count = mesh.faceVertexCounts[face];
        if (count < 3 || corner + std::size_t(count) > mesh.faceVertexIndices.size())
            throw Error("ray scene: face " + std::to_string(face) + " has " + std::to_string(count) +
                        " corners or runs past the face-vertex indices");
        for (std::int32_t c = 0; c < count; ++c) {
            const std::int32_t v = mesh.faceVertexIndices[corner + std::size_t(c)];
            if (v < 0 || std::size_t(v) >= mesh.points.size())
                throw Error("ray scene: face " + std::to_string(face) + " uses vertex " + std::to_string(v) +
                            " of " + std::to_string(mesh.points.size()));
        }
        corner += std::size_t(count);
    }
    forEachFanTriangle(mesh.faceVertexCounts, mesh.faceVertexIndices,
                       [&](std::size_t face, const std::array<std::int32_t, 3>& v) {
                           for (std::int32_t vertex : v) triangles.push_back(std::uint32_t(vertex));
                           faceOfTriangle.push_back(std::uint32_t(face));
                       });
}

static_assert(RayScene::kMaxWorldCoordinate == 1e12, "the message below quotes the limit");

// The mesh's points in world space, each checked finite and within kMaxWorldCoordinate.
std::vector<Imath::V3f> worldPoints(const RenderMesh& mesh, const Imath::M44d& objectToWorld) {
    std::vector<Imath::V3f> world(mesh.points.size());
    for (std::size_t v = 0; v < mesh.points.size(); ++v) {
        Imath::V3d p;
        objectToWorld.multVecMatrix(Imath::V3d(mesh.points[v]), p);
        if (!(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) <= RayScene::kMaxWorldCoordinate))
            throw Error("ray scene: point " + std::to_string(v) + " lies at (" + std::to_string(p.x) + ", " +
                        std::to_string(p.y) + ", " + std::to_string(p.z) + ") in world space: not finite or beyond " +
                        "the 1e12 units from the origin a scene may span");
        world[v] = Imath::V3f(p);
    }
    return world;
}

}  // namespace

RayScene::RayScene(BuildQuality quality) {
    device_ = rtcNewDevice(embreeDeviceConfig().c_str());
    if (!device_) embreeFailure(nullptr, "creating a device");
    scene_ = rtcNewScene(device_);
    if (!scene_) embreeFailure(device_, "creating a scene");
    if (quality == BuildQuality::High) rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
}

RayScene::~RayScene() {
    if (scene_) rtcReleaseScene(scene_);
    if (device_) rtcReleaseDevice(device_);
}

std::uint32_t RayScene::addMesh(const RenderMesh& mesh, const Imath::M44d& objectToWorld) {
    Mesh added;
    fanTriangles(mesh, added.triangles, added.faceOfTriangle);
    const std::vector<Imath::V3f> world = worldPoints(mesh, objectToWorld);
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!geometry) embreeFailure(device_, "creating a triangle geometry");
    auto* points = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                               3 * sizeof(float), world.size()));
    auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), added.faceOfTriangle.size()));
    if (!points || !indices) {
        rtcReleaseGeometry(geometry);
        embreeFailure(device_, "allocating mesh buffers");
    }
    for (std::size_t v = 0; v < world.size(); ++v) {
        points[3 * v + 0] = world[v].x;
        points[3 * v + 1] = world[v].y;
        points[3 * v + 2] = world[v].z;
        bounds_.extendBy(world[v]);
    }
    std::copy(added.triangles.begin(), added.triangles.end(), indices);
    rtcCommitGeometry(geometry);
    const unsigned id = rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);
    if (id != meshes_.size()) throw Error("ray scene: Embree numbered a geometry out of order");
    meshes_.push_back(std::move(added));
    extent_ = bounds_.isEmpty() ? 0.0f : (bounds_.max - bounds_.min).length();
    committed_ = false;
    return id;
}

void RayScene::commit() {
    rtcCommitScene(scene_);
    if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) embreeFailure(device_, "building the scene");
    committed_ = true;
}

std::array<std::uint32_t, 3> RayScene::triangleVertices(std::uint32_t prim, std::uint32_t triangle) const {
    const std::vector<std::uint32_t>& t = meshes_.at(prim).triangles;
    if (3 * std::size_t(triangle) + 2 >= t.size())
        throw Error("ray scene: triangle " + std::to_string(triangle) + " out of range for mesh " + std::to_string(prim));
    return {t[3 * triangle], t[3 * triangle + 1], t[3 * triangle + 2]};
}

std::span<const std::uint32_t> RayScene::triangles(std::uint32_t prim) const {
    if (prim >= meshes_.size())
        throw Error("ray scene: mesh " + std::to_string(prim) + " out of range (" + std::to_string(meshes_.size()) +
                    " meshes)");
    return meshes_[prim].triangles;
}

std::uint32_t RayScene::triangleFace(std::uint32_t prim, std::uint32_t triangle) const {
    return meshes_.at(prim).faceOfTriangle.at(triangle);
}

void RayScene::requireCommitted(const char* query) const {
    if (!committed_) throw Error(std::string("ray scene: ") + query + " on a scene that is not committed");
}

bool RayScene::occluded(const Ray& r) const {
    requireCommitted("occluded");
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray = toEmbree(r);
    rtcOccluded1(scene_, &context, &ray);
    return ray.tfar < 0.0f;  // Embree marks a blocked ray with tfar = -inf
}

void RayScene::occluded(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const {
    requireCommitted("occluded");
    requireSizes(rays.size(), blocked.size());
    constexpr std::size_t kStream = 64;
    RTCRay stream[kStream];
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (std::size_t first = 0; first < rays.size(); first += kStream) {
        const std::size_t n = std::min(kStream, rays.size() - first);
        for (std::size_t i = 0; i < n; ++i) stream[i] = toEmbree(rays[first + i]);
        rtcOccluded1M(scene_, &context, stream, unsigned(n), sizeof(RTCRay));
        for (std::size_t i = 0; i < n; ++i) blocked[first + i] = stream[i].tfar < 0.0f ? 1 : 0;
    }
}

void RayScene::requireSizes(std::size_t rays, std::size_t results) const {
    if (rays != results)
        throw Error("ray scene: " + std::to_string(results) + " results for " + std::to_string(rays) + " rays");
}

void RayScene::occludedCoherent(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const {
    requireCommitted("occluded");
    requireSizes(rays.size(), blocked.size());
    RTCIntersectContext context = coherentContext();
    RTCRay16 packet;
    for (std::size_t first = 0; first < rays.size(); first += kPacketSize) {
        const std::size_t n = std::min(kPacketSize, rays.size() - first);
        for (std::size_t i = 0; i < n; ++i) setPacketRay(packet, i, rays[first + i]);
        clearUnusedSlots(packet, n);
        const PacketMask mask(n);
        rtcOccluded16(mask.valid, scene_, &context, &packet);
        for (std::size_t i = 0; i < n; ++i) blocked[first + i] = packet.tfar[i] < 0.0f ? 1 : 0;
    }
}

void RayScene::intersectCoherent(std::span<const Ray> rays, std::span<std::optional<RayHit>> hits) const {
    requireCommitted("intersect");
    requireSizes(rays.size(), hits.size());
    RTCIntersectContext context = coherentContext();
    RTCRayHit16 packet;
    for (std::size_t first = 0; first < rays.size(); first += kPacketSize) {
        const std::size_t n = std::min(kPacketSize, rays.size() - first);
        for (std::size_t i = 0; i < n; ++i) {
            setPacketRay(packet.ray, i, rays[first + i]);
            packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
            packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
        }
        clearUnusedSlots(packet.ray, n);
        const PacketMask mask(n);
        rtcIntersect16(mask.valid, scene_, &context, &packet);
        for (std::size_t i = 0; i < n; ++i) {
            std::optional<RayHit>& hit = hits[first + i];
            hit.reset();
            if (packet.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID ||
                !shadeableNormal(packet.hit.Ng_x[i], packet.hit.Ng_y[i], packet.hit.Ng_z[i]))
                continue;
            hit.emplace();
            hit->prim = packet.hit.geomID[i];
            hit->triangle = packet.hit.primID[i];
            hit->u = packet.hit.u[i];
            hit->v = packet.hit.v[i];
            hit->t = packet.ray.tfar[i];
            hit->geometricNormal = {packet.hit.Ng_x[i], packet.hit.Ng_y[i], packet.hit.Ng_z[i]};
        }
    }
}

std::optional<RayHit> RayScene::intersect(const Ray& r) const {
    requireCommitted("intersect");
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit query{};
    query.ray = toEmbree(r);
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &query);
    if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID || !shadeableNormal(query.hit.Ng_x, query.hit.Ng_y, query.hit.Ng_z))
        return std::nullopt;
    RayHit hit;
    hit.prim = query.hit.geomID;
    hit.triangle = query.hit.primID;
    hit.u = query.hit.u;
    hit.v = query.hit.v;
    hit.t = query.ray.tfar;
    hit.geometricNormal = {query.hit.Ng_x, query.hit.Ng_y, query.hit.Ng_z};
    return hit;
}

}  // namespace opal
