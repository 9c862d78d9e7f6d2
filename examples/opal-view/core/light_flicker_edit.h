// A shadow-field light's flicker as the light panel and scripts set it: amplitude 0 to 1
// (0: steady), frequency 0 to 1000 Hz, and a seed that a layer's int holds (0 to
// 4294967295, saved as opal:flicker:seed). The ranges are the scene reader's, so a saved
// scene reads back what was set.
#pragma once

#include "delegate/hd/scene_delegate.h"

namespace opal::view {

// Throws opal::Error naming the value and its range, or saying that only shadow-field
// lights flicker, and leaves `light` as it was.
void setFlicker(hd::LightDesc& light, double amplitude, double frequency, double seed);

}  // namespace opal::view
