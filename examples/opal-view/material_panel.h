// The material panel: the selected mesh's sigma_s' and sigma_a per channel on logarithmic
// sliders bounded by its asset's editable range (mm^-1), or its albedo (a colour) and
// diffuse mean free path per channel (mm) converted to them; eta within the range,
// specular roughness, the presets, and the reset to the baked default.
#pragma once

#include "examples/opal-view/core/viewer_model.h"

#include <string>

namespace opal::view {

struct MaterialPanelState {
    bool artist = false;  // albedo + mean free path instead of sigma_s' and sigma_a
    std::string problem;  // why the last artist edit was refused
};

void drawMaterialPanel(ViewerModel& model, MaterialPanelState& state);

}  // namespace opal::view
