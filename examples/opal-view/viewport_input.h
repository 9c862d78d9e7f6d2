// Mouse and keys over the picture (not over a panel), as usdview and DCCs: Alt + left drag
// tumbles, Alt + middle tracks, Alt + right dollies, the wheel dollies; F frames all, R
// resets the camera; a left drag without Alt moves the selected point or sphere light on
// a sphere around the object (light_drag.h).
#pragma once

#include "examples/opal-view/core/viewer_model.h"

namespace opal::view {

void handleViewportInput(ViewerModel& model);

}  // namespace opal::view
