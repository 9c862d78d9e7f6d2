// The pixel probe over the picture (P): under the cursor, every AOV's scene-linear value and
// the display value shown there, in a tooltip; a left click (without Alt) selects the asset
// or shadow-field light the pixel shows (primId), for the material and light panels.
#pragma once

#include "delegate/output/image.h"
#include "examples/opal-view/core/viewer_model.h"

#include <string>

namespace opal::view {

// `shown`: the display-referred picture on screen (any resolution), showing `shownAov`.
void drawProbeTooltip(ViewerModel& model, const Image& shown, const std::string& shownAov);

}  // namespace opal::view
