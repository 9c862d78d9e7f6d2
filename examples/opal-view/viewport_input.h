// Mouse and keys over the picture (not over a panel): the pointer gestures of
// pointer_gestures.h on the camera and the selected point, sphere, spot or distant light; F frames
// all, R resets the camera; Ctrl+Z undoes, Ctrl+Shift+Z (or Ctrl+Y) redoes; H shows the
// keyboard help, P the pixel probe, G the light gizmos.
#pragma once

#include "examples/opal-view/core/viewer_model.h"
#include "examples/opal-view/panel_visibility.h"

namespace opal::view {

void handleViewportInput(ViewerModel& model, PanelVisibility& panels);

}  // namespace opal::view
