// Dragging a light in the viewport: a positional light stays on a sphere around the object
// (its distance from the centre kept) and goes where the cursor points, on the sphere's side
// facing the camera; past the sphere's silhouette it follows the silhouette. A distant light
// turns instead, as the camera tumbles: the side it comes from follows the cursor.
#pragma once

#include "examples/opal-view/core/orbit_camera.h"

namespace opal::view {

// The world-space direction of the ray through the image point (ndcX, ndcY), both in
// [-1, 1] with +y up, for a viewport of `aspect` (width / height).
Imath::V3d viewRay(const OrbitCamera& camera, double aspect, double ndcX, double ndcY);

// Where the ray from the eye along `ray` (unit) meets the sphere first; the silhouette
// point nearest the ray when it misses (or starts inside and faces away).
Imath::V3d pointOnSphere(const Imath::V3d& eye, const Imath::V3d& ray, const Imath::V3d& center, double radius);

// The light turned by a drag of (dx, dy) pixels (y down): about the camera's up axis by
// dx x kTurnDegreesPerPixel (right: the light comes more from the camera's right), then
// about the camera's right axis by dy x kTurnDegreesPerPixel (down: more from below). Its
// position stays.
inline constexpr double kTurnDegreesPerPixel = 0.25;
hd::LightDesc turnedLight(const OrbitCamera& camera, hd::LightDesc light, double dxPixels, double dyPixels);

}  // namespace opal::view
