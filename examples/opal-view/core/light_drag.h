// Dragging a light in the viewport: the light stays on a sphere around the object (its
// distance from the centre kept) and goes where the cursor points, on the sphere's side
// facing the camera; past the sphere's silhouette it follows the silhouette.
#pragma once

#include "examples/opal-view/core/orbit_camera.h"

namespace opal::view {

// The world-space direction of the ray through the image point (ndcX, ndcY), both in
// [-1, 1] with +y up, for a viewport of `aspect` (width / height).
Imath::V3d viewRay(const OrbitCamera& camera, double aspect, double ndcX, double ndcY);

// Where the ray from the eye along `ray` (unit) meets the sphere first; the silhouette
// point nearest the ray when it misses (or starts inside and faces away).
Imath::V3d pointOnSphere(const Imath::V3d& eye, const Imath::V3d& ray, const Imath::V3d& center, double radius);

}  // namespace opal::view
