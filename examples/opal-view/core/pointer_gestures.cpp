#include "examples/opal-view/core/pointer_gestures.h"

#include "examples/opal-view/core/light_drag.h"

namespace opal::view {
namespace {

constexpr double DollyPixelsPerStep = 20.0;

}  // namespace

bool cameraGesture(OrbitCamera& camera, const Pointer& pointer) {
    bool moved = false;
    if (pointer.wheel != 0.0) {
        dolly(camera, pointer.wheel);
        moved = true;
    }
    if (!pointer.alt || (pointer.dx == 0.0 && pointer.dy == 0.0)) return moved;
    const double aspect = pointer.width / pointer.height;
    if (pointer.left) tumble(camera, pointer.dx, pointer.dy);
    else if (pointer.middle) track(camera, pointer.dx, pointer.dy, int(pointer.height), aspect);
    else if (pointer.right) dolly(camera, (pointer.dx - pointer.dy) / DollyPixelsPerStep);
    else return moved;
    return true;
}

namespace {

bool dragsLight(const Pointer& pointer) { return !pointer.alt && pointer.left && (pointer.dx != 0.0 || pointer.dy != 0.0); }

}  // namespace

std::optional<hd::LightDesc> distantLightGesture(const OrbitCamera& camera, const Pointer& pointer,
                                                 const hd::LightDesc& light) {
    if (!dragsLight(pointer)) return std::nullopt;
    return turnedLight(camera, light, pointer.dx, pointer.dy);
}

std::optional<Imath::V3d> lightGesture(const OrbitCamera& camera, const Pointer& pointer, const Imath::V3d& light,
                                       const Imath::V3d& center) {
    if (!dragsLight(pointer)) return std::nullopt;
    const double ndcX = 2.0 * pointer.x / pointer.width - 1.0, ndcY = 1.0 - 2.0 * pointer.y / pointer.height;
    const Imath::V3d ray = viewRay(camera, pointer.width / pointer.height, ndcX, ndcY);
    return pointOnSphere(eyePosition(camera), ray, center, (light - center).length());
}

}  // namespace opal::view
