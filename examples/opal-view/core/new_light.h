// The lights the viewer adds (the light panel's Add, the script's `light add`), placed for
// the object in view: a point light above, left of and in front of the bounding sphere,
// three radii away, bright enough that a white diffuse surface facing it would be lit with
// irradiance pi (radiance about 1); a distant light from the same direction at UsdLux's
// fallback intensity; a white dome of radiance 1. Values as a layer stores them
// (layer_precision.h).
#pragma once

#include "examples/opal-view/core/scene_bounds.h"
#include "examples/scene/scene.h"

#include <optional>
#include <string_view>

namespace opal::view {

enum class NewLightKind { Point, Distant, Dome };

// "point", "distant" or "dome".
std::optional<NewLightKind> newLightKind(std::string_view name);
const char* newLightKindName(NewLightKind kind);

scene::SceneLight newLight(NewLightKind kind, const BoundingSphere& bounds);

}  // namespace opal::view
