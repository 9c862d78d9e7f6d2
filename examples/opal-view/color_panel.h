// The colour panel: the OCIO display and view, the exposure, and the AOV shown (one of
// `aovs`, those the delegate renders).
#pragma once

#include <string>
#include <vector>

#include "examples/opal-view/core/display_picture.h"
#include "examples/opal-view/display_settings.h"

namespace opal::view {

void drawColorPanel(DisplayPicture& picture, DisplaySettings& settings, const std::vector<std::string>& aovs);

}  // namespace opal::view
