#include "examples/opal-view/core/orbit_camera.h"

#include "examples/opal-view/core/layer_precision.h"
#include "schema/error.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace opal::view {
namespace {

constexpr double DegreesPerPixel = 0.25;
constexpr double MaxPitch = 89.0;

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }
double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

// The camera's +Z axis: from the target towards the eye.
Imath::V3d backward(const OrbitCamera& c) {
    const double y = radians(c.yaw), p = radians(c.pitch);
    return {std::cos(p) * std::sin(y), std::sin(p), std::cos(p) * std::cos(y)};
}

Imath::V3d rightOf(const OrbitCamera& c) {
    return Imath::V3d(0.0, 1.0, 0.0).cross(backward(c)).normalized();
}

Imath::V3d upOf(const OrbitCamera& c) { return backward(c).cross(rightOf(c)); }

}  // namespace

Imath::V2d visibleFilm(const OrbitCamera& camera, double aspect) {
    if (aspect > camera.horizontalAperture / camera.verticalAperture)
        return {camera.verticalAperture * aspect, camera.verticalAperture};
    return {camera.horizontalAperture, camera.horizontalAperture / aspect};
}

Imath::V3d eyePosition(const OrbitCamera& camera) { return camera.target + backward(camera) * camera.distance; }

Imath::M44d cameraToWorld(const OrbitCamera& camera) {
    const Imath::V3d x = rightOf(camera), y = upOf(camera), z = backward(camera), eye = eyePosition(camera);
    return Imath::M44d(x.x, x.y, x.z, 0.0, y.x, y.y, y.z, 0.0, z.x, z.y, z.z, 0.0, eye.x, eye.y, eye.z, 1.0);
}

double halfFieldOfView(const OrbitCamera& camera, double aspect) {
    const Imath::V2d film2 = visibleFilm(camera, aspect);
    const double film = std::min(film2.x, film2.y);
    return std::atan(0.5 * film / camera.focalLength);
}

void setFocalLength(OrbitCamera& camera, double focalLength) {
    if (!(focalLength >= 1.0 && focalLength <= 10000.0))
        throw Error("focal length " + std::to_string(focalLength) + " is outside 1 to 10000");
    camera.focalLength = focalLength;
}

double horizontalFieldOfView(const OrbitCamera& camera, double aspect) {
    return degrees(2.0 * std::atan(0.5 * visibleFilm(camera, aspect).x / camera.focalLength));
}

void setHorizontalFieldOfView(OrbitCamera& camera, double fieldOfView, double aspect) {
    if (!(fieldOfView >= 1.0 && fieldOfView <= 170.0))
        throw Error("field of view " + std::to_string(fieldOfView) + " degrees is outside 1 to 170");
    setFocalLength(camera, 0.5 * visibleFilm(camera, aspect).x / std::tan(radians(0.5 * fieldOfView)));
}

void setClipping(OrbitCamera& camera, double nearClip, double farClip) {
    if (!(nearClip > 0.0 && farClip > nearClip && std::isfinite(farClip)))
        throw Error("clipping range " + std::to_string(nearClip) + " to " + std::to_string(farClip) +
                    " is not 0 < near < far");
    camera.nearClip = nearClip;
    camera.farClip = farClip;
}

void setAutomaticClipping(OrbitCamera& camera) {
    camera.nearClip.reset();
    camera.farClip.reset();
}

hd::CameraDesc cameraDesc(const OrbitCamera& camera, const BoundingSphere& scene) {
    hd::CameraDesc desc;
    desc.transform = cameraToWorld(camera);
    desc.focalLength = camera.focalLength;
    desc.horizontalAperture = camera.horizontalAperture;
    desc.verticalAperture = camera.verticalAperture;
    const double reach = (eyePosition(camera) - scene.center).length() + scene.radius;
    desc.nearClip = camera.nearClip.value_or(reach * 1e-4);
    desc.farClip = camera.farClip.value_or(reach * 2.0);
    return storable(desc);
}

void tumble(OrbitCamera& camera, double dxPixels, double dyPixels) {
    camera.yaw = std::remainder(camera.yaw - dxPixels * DegreesPerPixel, 360.0);
    camera.pitch = std::clamp(camera.pitch + dyPixels * DegreesPerPixel, -MaxPitch, MaxPitch);
}

void track(OrbitCamera& camera, double dxPixels, double dyPixels, int viewportHeight, double aspect) {
    // World units per pixel at the target's depth, so the target follows the cursor.
    const double film = visibleFilm(camera, aspect).y;
    const double perPixel = camera.distance * film / camera.focalLength / std::max(viewportHeight, 1);
    camera.target += (-dxPixels * rightOf(camera) + dyPixels * upOf(camera)) * perPixel;
}

void dolly(OrbitCamera& camera, double steps) { camera.distance *= std::pow(0.9, steps); }

void frame(OrbitCamera& camera, const BoundingSphere& sphere, double aspect) {
    camera.target = sphere.center;
    camera.distance = sphere.radius / std::sin(halfFieldOfView(camera, aspect));
}

OrbitCamera orbitFromCamera(const hd::CameraDesc& desc, const BoundingSphere& scene) {
    const Imath::M44d& m = desc.transform;
    const Imath::V3d eye(m[3][0], m[3][1], m[3][2]);
    const Imath::V3d back = Imath::V3d(m[2][0], m[2][1], m[2][2]).normalized();
    OrbitCamera camera;
    camera.focalLength = desc.focalLength;
    camera.horizontalAperture = desc.horizontalAperture;
    camera.verticalAperture = desc.verticalAperture;
    const double along = (scene.center - eye).dot(-back);
    camera.distance = along > 0.0 ? along : (scene.center - eye).length();
    camera.target = eye - back * camera.distance;
    camera.pitch = std::clamp(degrees(std::asin(std::clamp(back.y, -1.0, 1.0))), -MaxPitch, MaxPitch);
    camera.yaw = degrees(std::atan2(back.x, back.z));
    return camera;
}

}  // namespace opal::view
