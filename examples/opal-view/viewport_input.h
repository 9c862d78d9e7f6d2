// Mouse and keys over the picture (not over a panel): the pointer gestures of
// pointer_gestures.h on the camera and the selected point, sphere or spot light; F frames
// all, R resets the camera.
#pragma once

#include "examples/opal-view/core/viewer_model.h"

namespace opal::view {

void handleViewportInput(ViewerModel& model);

}  // namespace opal::view
