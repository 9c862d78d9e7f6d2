// The bounding sphere of what a scene shows (every visible mesh's render mesh placed in
// world space): what "frame all" fits into the view and what a dragged light circles.
#pragma once

#include "examples/scene/scene.h"

#include <Imath/ImathVec.h>

namespace opal::view {

struct BoundingSphere {
    Imath::V3d center{0.0, 0.0, 0.0};
    double radius = 1.0;
};

// The centre of the world-space bounding box and the farthest point's distance from it.
// A scene without visible meshes (or points) gives the unit sphere at the origin.
BoundingSphere sceneBounds(const scene::Scene& scene);
// The same for one mesh of the scene (what "frame selection" fits); throws opal::Error
// naming the path when the scene has no such mesh.
BoundingSphere meshBounds(const scene::Scene& scene, const hd::SdfPath& mesh);

}  // namespace opal::view
