// Edits as a scene layer can hold them: material, light and camera parameters are float
// attributes in USD (color3f, float, float2), so the viewer rounds an edit to float before
// rendering it. The picture it shows is then the one opal-render draws from the layer the
// viewer saves (usda_export.h), bit for bit, not one a double the file cannot keep.
#pragma once

#include "delegate/hd/scene_delegate.h"

namespace opal::view {

double storable(double value);
hd::MaterialDesc storable(hd::MaterialDesc desc);
// Transforms stay double (matrix4d xformOp:transform).
hd::LightDesc storable(hd::LightDesc desc);
hd::CameraDesc storable(hd::CameraDesc desc);

}  // namespace opal::view
