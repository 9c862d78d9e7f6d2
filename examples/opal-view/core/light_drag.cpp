#include "examples/opal-view/core/light_drag.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace opal::view {

Imath::V3d viewRay(const OrbitCamera& camera, double aspect, double ndcX, double ndcY) {
    const Imath::V2d film = visibleFilm(camera, aspect);
    const Imath::V3d local(ndcX * 0.5 * film.x / camera.focalLength, ndcY * 0.5 * film.y / camera.focalLength, -1.0);
    Imath::V3d world;
    cameraToWorld(camera).multDirMatrix(local, world);
    return world.normalized();
}

Imath::V3d pointOnSphere(const Imath::V3d& eye, const Imath::V3d& ray, const Imath::V3d& center, double radius) {
    const Imath::V3d toEye = eye - center;
    const double b = toEye.dot(ray), c = toEye.dot(toEye) - radius * radius;
    const double discriminant = b * b - c;
    if (discriminant >= 0.0) {
        const double root = std::sqrt(discriminant);
        const double t = -b - root >= 0.0 ? -b - root : -b + root;
        if (t >= 0.0) return eye + ray * t;
    }
    // The ray's point nearest the centre, pushed out to the sphere.
    Imath::V3d off = eye + ray * std::max(-b, 0.0) - center;
    if (off.length() < 1e-12 * std::max(radius, 1.0)) off = toEye;
    return center + off.normalized() * radius;
}

hd::LightDesc turnedLight(const OrbitCamera& camera, hd::LightDesc light, double dxPixels, double dyPixels) {
    const Imath::M44d view = cameraToWorld(camera);
    const Imath::V3d right(view[0][0], view[0][1], view[0][2]), up(view[1][0], view[1][1], view[1][2]);
    const double perPixel = kTurnDegreesPerPixel * std::numbers::pi / 180.0;
    Imath::M44d yaw, pitch;
    yaw.setAxisAngle(up, dxPixels * perPixel);
    pitch.setAxisAngle(right, dyPixels * perPixel);
    // Row vectors: the light's axes turned, its translation (row 3) kept.
    const Imath::V3d at(light.transform[3][0], light.transform[3][1], light.transform[3][2]);
    light.transform = light.transform * yaw * pitch;
    light.transform[3][0] = at.x;
    light.transform[3][1] = at.y;
    light.transform[3][2] = at.z;
    return light;
}

}  // namespace opal::view
