// What the picture is shown as, besides the OCIO display and view (DisplayPicture): the
// AOV, the exposure and the gamma. `version` grows with every change, so the picture is
// redone.
#pragma once

#include "examples/opal-view/core/display_picture.h"

#include <string>

namespace opal::view {

struct DisplaySettings {
    std::string aov = "color";
    DisplayGrade grade;  // exposure before the view transform, gamma after it
    int version = 0;
};

}  // namespace opal::view
