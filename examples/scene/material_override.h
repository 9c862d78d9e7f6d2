// A host-side material override (opal-render --material PRESET): one Material added to
// the scene with a preset's coefficients and the default specular layer, and every mesh
// bound to it, replacing whatever the scene bound.
#pragma once

#include "examples/scene/scene.h"

#include <string_view>

namespace opal::scene {

// Where the override material lives; a scene may not use this path itself.
inline const hd::SdfPath OverrideMaterialPath = "/_OpalRender/MaterialOverride";

// Throws opal::Error for an unknown preset (listing the presets) or a scene that already
// has a prim at OverrideMaterialPath.
void overrideMaterials(Scene& scene, std::string_view preset);

}  // namespace opal::scene
