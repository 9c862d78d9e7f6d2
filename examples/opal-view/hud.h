// The heads-up line over the picture: the interface's frame rate and its own drawing time
// per frame (without the wait that paces it), the last relight (sync), the
// samples per pixel the picture holds so far, and the scene's size; the newest message
// (a delegate warning or error) under it.
#pragma once

#include "examples/opal-view/core/viewer_model.h"

#include <string>

namespace opal::view {

struct HudFigures {
    double frameMs = 0.0;  // from one frame's start to the next's: 1000 / the frame rate
    double drawMs = 0.0;   // of that, all but the wait that paces the frames
    std::string message;
};

void drawHud(const ViewerModel& model, const HudFigures& figures);

}  // namespace opal::view
