// What the picture is shown as, besides the OCIO display and view (DisplayPicture): the
// AOV and the exposure. `version` grows with every change, so the picture is redone.
#pragma once

#include <string>

namespace opal::view {

struct DisplaySettings {
    std::string aov = "color";
    double exposure = 0.0;  // stops, applied in scene-linear before the view transform
    int version = 0;
};

}  // namespace opal::view
