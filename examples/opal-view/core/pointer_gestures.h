// What the mouse does over the picture, as usdview and DCCs: Alt + left drag tumbles, Alt +
// middle tracks, Alt + right dollies, the wheel dollies; a left drag without Alt moves the
// selected light on its sphere around the object, or turns the selected distant light
// (light_drag.h). Window coordinates, y down.
#pragma once

#include "examples/opal-view/core/orbit_camera.h"

#include <optional>

namespace opal::view {

struct Pointer {
    double x = 0.0, y = 0.0;    // position
    double dx = 0.0, dy = 0.0;  // movement since the last frame
    double wheel = 0.0;         // notches, positive away from the user
    bool left = false, middle = false, right = false, alt = false;
    double width = 1.0, height = 1.0;  // the window
};

// Applies the camera gestures; true when the camera moved.
bool cameraGesture(OrbitCamera& camera, const Pointer& pointer);

// Where a left drag without Alt puts a light now at `light` (kept at its distance from
// `center`); nothing when the pointer does not drag it.
std::optional<Imath::V3d> lightGesture(const OrbitCamera& camera, const Pointer& pointer, const Imath::V3d& light,
                                       const Imath::V3d& center);

// The distant light `light` turned by a left drag without Alt; nothing when the pointer does
// not drag it.
std::optional<hd::LightDesc> distantLightGesture(const OrbitCamera& camera, const Pointer& pointer,
                                                 const hd::LightDesc& light);

}  // namespace opal::view
