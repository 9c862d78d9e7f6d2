// The lights the viewer adds (the light panel's Add, the script's `light add`), placed for
// the object in view: a point light above, left of and in front of the bounding sphere,
// three radii away, bright enough that a white diffuse surface facing it would be lit with
// irradiance pi (radiance about 1); a sphere light of a quarter of the object's radius at
// the same place, as bright; a spot light there too (that sphere aimed at the centre, its
// cone of 30 degrees holding the whole object, which subtends 19.5); a distant light from
// the same direction at UsdLux's fallback intensity; a white dome of radiance 1. Values as
// a layer stores them (layer_precision.h).
#pragma once

#include "examples/opal-view/core/scene_bounds.h"
#include "examples/scene/scene.h"

#include <optional>
#include <span>
#include <string_view>

namespace opal::view {

enum class NewLightKind { Point, Sphere, Spot, Distant, Dome };

// "point", "sphere", "spot", "distant" or "dome".
std::optional<NewLightKind> newLightKind(std::string_view name);
const char* newLightKindName(NewLightKind kind);
// Every kind, in the order the panel offers them.
std::span<const NewLightKind> newLightKinds();

scene::SceneLight newLight(NewLightKind kind, const BoundingSphere& bounds);

// A baked light (light_layer.h) where the point light would go, as its layer describes it.
scene::SceneLight newShadowFieldLight(hd::LightDesc baked, const BoundingSphere& bounds);

}  // namespace opal::view
