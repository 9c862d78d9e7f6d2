#include "examples/opal-view/core/scene_bounds.h"

#include <Imath/ImathBox.h>

#include <algorithm>
#include <cmath>

namespace opal::view {
namespace {

template <class Visit>
void forEachWorldPoint(const scene::Scene& scene, Visit&& visit) {
    for (const auto& [path, mesh] : scene.meshes) {
        if (!mesh.desc.visible || !mesh.desc.asset) continue;
        for (const Imath::V3f& p : mesh.desc.asset->mesh.points) visit(Imath::V3d(p) * mesh.desc.transform);
    }
}

}  // namespace

BoundingSphere sceneBounds(const scene::Scene& scene) {
    Imath::Box3d box;
    forEachWorldPoint(scene, [&](const Imath::V3d& p) { box.extendBy(p); });
    if (box.isEmpty()) return {};
    BoundingSphere sphere{box.center(), 0.0};
    forEachWorldPoint(scene, [&](const Imath::V3d& p) { sphere.radius = std::max(sphere.radius, (p - sphere.center).length()); });
    // A single point still needs a size to look at.
    if (!(sphere.radius > 0.0)) sphere.radius = 1.0;
    return sphere;
}

}  // namespace opal::view
