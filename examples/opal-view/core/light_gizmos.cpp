#include "examples/opal-view/core/light_gizmos.h"

#include "examples/opal-view/core/edited_scene.h"

namespace opal::view {
namespace {

// A distant light's arrow: from 2.5 to 1.25 object radii out, on the side its light comes from.
constexpr double ArrowTail = 2.5, ArrowHead = 1.25;

// The light's +Z axis: where a distant light comes from (it travels along -Z).
Imath::V3d towardLight(const hd::LightDesc& light) {
    Imath::V3d z;
    light.transform.multDirMatrix(Imath::V3d(0.0, 0.0, 1.0), z);
    return z.normalized();
}

std::optional<LightGizmo> gizmoOf(const hd::SdfPath& path, const hd::LightDesc& light, const GizmoView& view) {
    const auto project = [&](const Imath::V3d& p) { return projectToViewport(*view.camera, view.width, view.height, p); };
    LightGizmo gizmo{path, LightGizmo::Shape::Marker, {}, {}, view.selected == path};
    switch (light.kind) {
    case hd::LightKind::Sphere:
    case hd::LightKind::ShadowField: {
        const std::optional<Imath::V2d> at = project(lightPosition(light));
        if (!at) return std::nullopt;
        gizmo.at = gizmo.from = *at;
        return gizmo;
    }
    case hd::LightKind::Distant: {
        const Imath::V3d z = towardLight(light);
        const std::optional<Imath::V2d> tail = project(view.bounds.center + z * (ArrowTail * view.bounds.radius));
        const std::optional<Imath::V2d> head = project(view.bounds.center + z * (ArrowHead * view.bounds.radius));
        if (!tail || !head) return std::nullopt;
        gizmo.shape = LightGizmo::Shape::Arrow;
        gizmo.from = *tail;
        gizmo.at = *head;
        return gizmo;
    }
    case hd::LightKind::Dome: return std::nullopt;
    }
    return std::nullopt;
}

}  // namespace

std::optional<Imath::V2d> projectToViewport(const OrbitCamera& camera, double width, double height,
                                            const Imath::V3d& world) {
    Imath::V3d local;
    cameraToWorld(camera).inverse().multVecMatrix(world, local);
    if (!(local.z < 0.0)) return std::nullopt;
    // The inverse of light_drag.h's viewRay: film millimetres at the focal length, then NDC.
    const Imath::V2d film = visibleFilm(camera, width / height);
    const double ndcX = local.x / -local.z * camera.focalLength / (0.5 * film.x);
    const double ndcY = local.y / -local.z * camera.focalLength / (0.5 * film.y);
    return Imath::V2d((ndcX + 1.0) * 0.5 * width, (1.0 - ndcY) * 0.5 * height);
}

std::vector<LightGizmo> lightGizmos(const scene::Scene& scene, const GizmoView& view) {
    std::vector<LightGizmo> gizmos;
    for (const auto& [path, light] : scene.lights)
        if (std::optional<LightGizmo> gizmo = gizmoOf(path, light.desc, view)) gizmos.push_back(std::move(*gizmo));
    return gizmos;
}

}  // namespace opal::view
