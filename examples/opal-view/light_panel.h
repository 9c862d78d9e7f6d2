// The light panel: every light of the scene, the selected one's intensity, exposure and
// colour, and (for a point or sphere light) its position, which a left-button drag in the
// viewport changes.
#pragma once

#include "examples/opal-view/core/viewer_model.h"

namespace opal::view {

void drawLightPanel(ViewerModel& model);

}  // namespace opal::view
