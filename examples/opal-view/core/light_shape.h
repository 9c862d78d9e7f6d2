// A light's type-specific parameters as the light panel and scripts set them, by name:
//   radius    a sphere or spot light's radius (scene units, >= 0); not a point light's
//             (treatAsPoint), whose size is none
//   cone      a sphere light's shaping cone angle (degrees off its -Z axis, 0 to 180): the
//             light becomes a spot
//   softness  a spot light's cone softness (0 to 1)
//   angle     a distant light's angular diameter (degrees, 0 to 180)
// The ranges are the scene reader's, so a saved scene reads back what was set.
#pragma once

#include "delegate/hd/scene_delegate.h"

#include <span>
#include <string_view>

namespace opal::view {

// The names above, in that order.
std::span<const std::string_view> lightShapeParameters();

// Whether `light` has the parameter (a point light has no radius, a sphere light without a
// cone no softness, only a distant light an angle).
bool hasShapeParameter(const hd::LightDesc& light, std::string_view parameter);

// Sets it; throws opal::Error naming the parameter and the range, or saying which lights
// have it, and leaves `light` as it was.
void setShapeParameter(hd::LightDesc& light, std::string_view parameter, double value);

}  // namespace opal::view
