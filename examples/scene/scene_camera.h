// A scene's Camera prim (UsdGeomCamera) read into the delegate's hd::CameraDesc: a
// perspective camera looking down its -Z axis with focalLength, horizontalAperture,
// verticalAperture (one unit, only ratios matter) and clippingRange, with UsdGeom's
// fallbacks (50, 20.955, 15.2908, (1, 1000000)).
#pragma once

#include "delegate/hd/scene_delegate.h"
#include "examples/scene/prim_reader.h"

namespace opal::scene {

// Throws UsdaError at the attribute at fault: a non-positive focal length or aperture,
// a clipping range that is not 0 < near < far, an orthographic projection, or a
// standard attribute (aperture offsets, fStop, ...) away from its fallback.
hd::CameraDesc readCamera(PrimReader& reader, const Imath::M44d& objectToWorld);

}  // namespace opal::scene
