// The light panel: add a point, distant or dome light; every light of the scene with a box
// that enables it; the selected one's intensity, exposure and colour, (for a point or sphere
// light) its position, which a left-button drag in the viewport changes, its name and removal.
#pragma once

#include "examples/opal-view/core/viewer_model.h"

#include <string>

namespace opal::view {

// `problem`: the last refused rename or removal, shown until one succeeds.
void drawLightPanel(ViewerModel& model, std::string& problem);

// A light's intensity (logarithmic) and exposure sliders; `id` keeps two sets of them in
// one window apart ("##dome"). True when either changed.
bool emissionSliders(hd::LightDesc& light, const char* id = "");

}  // namespace opal::view
