// A light's UsdLux colour temperature as the light panel and scripts set it: the light's
// colour is then multiplied by a black body's at that temperature (delegate/hd/
// scene_delegate.h).
#pragma once

#include "delegate/hd/scene_delegate.h"

namespace opal::view {

inline constexpr double kMinColorTemperature = 500.0, kMaxColorTemperature = 40000.0;  // kelvin

// Kelvin in [500, 40000] turns the temperature on at that value; 0 turns it off (the
// value is kept). Throws opal::Error naming the range for anything else.
void setColorTemperature(hd::LightDesc& light, double kelvin);

}  // namespace opal::view
