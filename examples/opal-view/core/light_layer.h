// A baked light layer (what `opal-bake light` writes: one OpalShadowFieldLight prim naming
// its sidecar) read as the light the viewer adds, as the scene reader reads a light prim
// that references it: the layer's intensity, colour, exposure, flicker and field, its
// field's path resolved against the layer.
#pragma once

#include "delegate/hd/scene_delegate.h"

#include <filesystem>

namespace opal::view {

// Throws opal::Error naming the file: missing, not USDA, without an OpalShadowFieldLight
// (its defaultPrim, else the prim named as the file), or with a bad attribute (at its line).
hd::LightDesc readLightLayer(const std::filesystem::path& file);

}  // namespace opal::view
