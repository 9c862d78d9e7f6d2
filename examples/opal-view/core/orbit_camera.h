// The viewer's free camera, as usdview and DCCs move it: it orbits a target at a distance
// (yaw about world +Y, pitch above the horizon, no roll). Tumble turns it about the target,
// track slides target and camera in the image plane, dolly changes the distance, frame
// fits a bounding sphere into the view. Pixel deltas are the mouse's (y grows downward).
#pragma once

#include "delegate/hd/scene_delegate.h"
#include "examples/opal-view/core/scene_bounds.h"

#include <Imath/ImathMatrix.h>
#include <Imath/ImathVec.h>

#include <optional>

namespace opal::view {

struct OrbitCamera {
    Imath::V3d target{0.0, 0.0, 0.0};
    double distance = 10.0;
    double yaw = 0.0;    // degrees about +Y; 0 looks down -Z
    double pitch = 0.0;  // degrees above the horizon, within +-89
    double focalLength = 50.0;
    double horizontalAperture = 36.0;  // same unit as the focal length
    double verticalAperture = 24.0;
    // Clipping planes (distances along the view axis); unset, cameraDesc picks planes
    // that hold the whole scene from wherever the camera is.
    std::optional<double> nearClip, farClip;
};

// The film the viewport shows: the camera's film fitted into the viewport's aspect (width
// / height) as the delegate fits it (usdview's "fit": all of it visible, the other side
// extended), width and height.
Imath::V2d visibleFilm(const OrbitCamera& camera, double aspect);

// Camera to world (row vectors, the camera looking down its -Z axis, +Y up in the image).
Imath::M44d cameraToWorld(const OrbitCamera& camera);
Imath::V3d eyePosition(const OrbitCamera& camera);
// A UsdGeomCamera with the camera's film (the delegate fits it into the viewport), with
// the camera's clipping planes, or without them planes that hold the whole sphere `scene`
// from wherever the camera is, its values as a layer stores them (layer_precision.h).
hd::CameraDesc cameraDesc(const OrbitCamera& camera, const BoundingSphere& scene);
// Half the smaller field of view, radians, for a viewport of this aspect (width / height).
double halfFieldOfView(const OrbitCamera& camera, double aspect);

// A focal length in [1, 10000] (the film's unit); throws opal::Error naming the range.
void setFocalLength(OrbitCamera& camera, double focalLength);
// The horizontal field of view of the film the viewport shows (visibleFilm), degrees; the
// setter changes the focal length to give it (throws opal::Error outside 1 to 170 degrees,
// or for a focal length setFocalLength refuses).
double horizontalFieldOfView(const OrbitCamera& camera, double aspect);
void setHorizontalFieldOfView(OrbitCamera& camera, double degrees, double aspect);
// Fixed clipping planes, 0 < near < far (throws opal::Error naming both otherwise), or
// automatic ones again.
void setClipping(OrbitCamera& camera, double nearClip, double farClip);
void setAutomaticClipping(OrbitCamera& camera);

void tumble(OrbitCamera& camera, double dxPixels, double dyPixels);
void track(OrbitCamera& camera, double dxPixels, double dyPixels, int viewportHeight, double aspect);
// steps > 0 moves closer (a wheel notch is one step: 10% of the distance).
void dolly(OrbitCamera& camera, double steps);
// Target the sphere's centre at the distance where it just fits the view, keeping the angles.
void frame(OrbitCamera& camera, const BoundingSphere& sphere, double aspect);
// The orbit camera that sees what `desc` sees (roll dropped), orbiting the point on its view
// axis nearest `scene`'s centre (the centre's distance when it lies behind the camera).
OrbitCamera orbitFromCamera(const hd::CameraDesc& desc, const BoundingSphere& scene);

}  // namespace opal::view
