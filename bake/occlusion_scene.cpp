#include "bake/occlusion_scene.h"

#include "schema/error.h"

#include <Imath/ImathBox.h>

#include <limits>
#include <string>

namespace opal {

namespace {

std::size_t triangleCount(const RenderMesh& mesh) {
    std::size_t n = 0;
    for (std::int32_t c : mesh.faceVertexCounts) n += c >= 3 ? std::size_t(c - 2) : 0;
    return n;
}

void fillTriangles(const RenderMesh& mesh, std::uint32_t* out) {
    std::size_t corner = 0;
    for (std::int32_t c : mesh.faceVertexCounts) {
        for (std::int32_t t = 1; t + 1 < c; ++t) {
            *out++ = std::uint32_t(mesh.faceVertexIndices[corner]);
            *out++ = std::uint32_t(mesh.faceVertexIndices[corner + t]);
            *out++ = std::uint32_t(mesh.faceVertexIndices[corner + t + 1]);
        }
        corner += std::size_t(c);
    }
}

}  // namespace

OcclusionScene::OcclusionScene(const RenderMesh& mesh) {
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw Error("Embree: cannot create a device (error " + std::to_string(rtcGetDeviceError(nullptr)) + ")");
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.points.size()));
    Imath::Box3f box;
    for (std::size_t v = 0; v < mesh.points.size(); ++v) {
        vertices[3 * v + 0] = mesh.points[v].x;
        vertices[3 * v + 1] = mesh.points[v].y;
        vertices[3 * v + 2] = mesh.points[v].z;
        box.extendBy(mesh.points[v]);
    }
    extent_ = box.isEmpty() ? 0.0f : (box.max - box.min).length();
    auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), triangleCount(mesh)));
    fillTriangles(mesh, indices);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene_, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene_);
}

OcclusionScene::~OcclusionScene() {
    if (scene_) rtcReleaseScene(scene_);
    if (device_) rtcReleaseDevice(device_);
}

bool OcclusionScene::occluded(const Imath::V3f& origin, const Imath::V3f& dir, float tNear, float tFar) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray{};
    ray.org_x = origin.x;
    ray.org_y = origin.y;
    ray.org_z = origin.z;
    ray.dir_x = dir.x;
    ray.dir_y = dir.y;
    ray.dir_z = dir.z;
    ray.tnear = tNear;
    ray.tfar = tFar;
    ray.mask = std::numeric_limits<unsigned>::max();
    rtcOccluded1(scene_, &context, &ray);
    return ray.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

}  // namespace opal
