// The environment panel: the scene's dome (core/environment_edit.h) with its lat-long
// image (a path, loaded on Enter or the button), its turn about the up axis, intensity and
// exposure, and whether it shows as the background; a button adds a dome when there is none.
#pragma once

#include "examples/opal-view/core/viewer_model.h"

#include <string>

namespace opal::view {

struct EnvironmentPanelState {
    std::string texture;  // the path being typed
    std::string problem;  // the last refused image, shown until one loads
};

void drawEnvironmentPanel(ViewerModel& model, EnvironmentPanelState& state);

}  // namespace opal::view
