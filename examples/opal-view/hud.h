// The heads-up line over the picture: interface frame time, the last relight (sync), the
// samples per pixel the picture holds so far, and the scene's size; the newest message
// (a delegate warning or error) under it.
#pragma once

#include "examples/opal-view/core/viewer_model.h"

#include <string>

namespace opal::view {

struct HudFigures {
    double frameMs = 0.0;
    std::string message;
};

void drawHud(const ViewerModel& model, const HudFigures& figures);

}  // namespace opal::view
