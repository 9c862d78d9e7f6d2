// The colour panel: the OCIO display and view, the exposure, and the AOV shown.
#pragma once

#include "examples/opal-view/core/display_picture.h"
#include "examples/opal-view/display_settings.h"

namespace opal::view {

void drawColorPanel(DisplayPicture& picture, DisplaySettings& settings);

}  // namespace opal::view
