// The material panel: the selected mesh's sigma_s' and sigma_a per channel on logarithmic
// sliders bounded by its asset's editable range (mm^-1), eta within the range, specular
// roughness, and the reset to the baked default.
#pragma once

#include "examples/opal-view/core/viewer_model.h"

namespace opal::view {

void drawMaterialPanel(ViewerModel& model);

}  // namespace opal::view
