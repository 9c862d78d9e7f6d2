#include "examples/opal-view/core/scene_bounds.h"

#include "schema/error.h"

#include <Imath/ImathBox.h>

#include <algorithm>
#include <cmath>

namespace opal::view {
namespace {

using Meshes = std::map<hd::SdfPath, scene::SceneMesh>;

template <class Visit>
void forEachWorldPoint(const Meshes& meshes, Visit&& visit) {
    for (const auto& [path, mesh] : meshes) {
        if (!mesh.desc.visible || !mesh.desc.asset) continue;
        for (const Imath::V3f& p : mesh.desc.asset->mesh.points) visit(Imath::V3d(p) * mesh.desc.transform);
    }
}

BoundingSphere boundsOf(const Meshes& meshes) {
    Imath::Box3d box;
    forEachWorldPoint(meshes, [&](const Imath::V3d& p) { box.extendBy(p); });
    if (box.isEmpty()) return {};
    BoundingSphere sphere{box.center(), 0.0};
    forEachWorldPoint(meshes, [&](const Imath::V3d& p) { sphere.radius = std::max(sphere.radius, (p - sphere.center).length()); });
    // A single point still needs a size to look at.
    if (!(sphere.radius > 0.0)) sphere.radius = 1.0;
    return sphere;
}

}  // namespace

BoundingSphere sceneBounds(const scene::Scene& scene) { return boundsOf(scene.meshes); }

BoundingSphere meshBounds(const scene::Scene& scene, const hd::SdfPath& mesh) {
    const auto it = scene.meshes.find(mesh);
    if (it == scene.meshes.end()) throw Error("no mesh <" + mesh + "> in the scene");
    return boundsOf(Meshes{*it});
}

}  // namespace opal::view
