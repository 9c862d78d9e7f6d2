// The light gizmos (core/light_gizmos.h) drawn over the picture and under the panels: a
// filled disc with a dark rim at each positional light, an arrow for each distant light,
// the selected light's in its own colour and with a ring.
#pragma once

#include "examples/opal-view/core/viewer_model.h"

namespace opal::view {

void drawLightGizmos(const ViewerModel& model);

}  // namespace opal::view
