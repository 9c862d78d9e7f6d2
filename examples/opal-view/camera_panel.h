// The camera panel: the free camera's focal length on a logarithmic slider with the
// horizontal field of view it gives the window, and the frame-all and reset buttons (F, R).
#pragma once

#include "examples/opal-view/core/viewer_model.h"

namespace opal::view {

void drawCameraPanel(ViewerModel& model);

}  // namespace opal::view
