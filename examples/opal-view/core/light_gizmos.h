// What the light gizmos over the picture show, in window pixels (y down), without a window:
// a marker where each point, sphere, spot or shadow-field light projects through the view
// camera (as the renderer projects: the film fitted into the viewport, orbit_camera.h), an
// arrow for each distant light along the way its light travels, ending at the object's
// bounding sphere; the selected light marked as such. Dome lights have none; disabled
// lights keep theirs (they can still be selected and moved); a light behind the camera
// has none.
#pragma once

#include "examples/opal-view/core/orbit_camera.h"
#include "examples/scene/scene.h"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace opal::view {

// The gizmos' fill colours (8-bit sRGB), amber and, for the selected light, cyan: apart
// from what a lit translucent asset or a dome shows.
inline constexpr std::array<std::uint8_t, 3> kGizmoColor{255, 176, 32}, kSelectedGizmoColor{32, 224, 255};

// Where `world` appears in a viewport of width x height pixels (x right, y down from the top
// left); nothing for a point at or behind the camera's plane.
std::optional<Imath::V2d> projectToViewport(const OrbitCamera& camera, double width, double height,
                                            const Imath::V3d& world);

struct LightGizmo {
    enum class Shape { Marker, Arrow };
    hd::SdfPath light;
    Shape shape = Shape::Marker;
    Imath::V2d at;    // the marker's centre, or the arrow's head
    Imath::V2d from;  // the arrow's tail (a marker: = at)
    bool selected = false;
};

struct GizmoView {
    const OrbitCamera* camera = nullptr;
    double width = 1.0, height = 1.0;  // the viewport, pixels
    BoundingSphere bounds;             // the object the distant lights' arrows point at
    std::optional<hd::SdfPath> selected;
};

std::vector<LightGizmo> lightGizmos(const scene::Scene& scene, const GizmoView& view);

}  // namespace opal::view
