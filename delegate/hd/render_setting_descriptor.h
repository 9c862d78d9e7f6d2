// A render setting as a delegate describes it (Hydra's HdRenderSettingDescriptor): a host
// builds its settings panel from these, and passes values back through setRenderSetting.
#pragma once

#include "delegate/hd/types.h"

#include <optional>
#include <string>
#include <vector>

namespace opal::hd {

struct RenderSettingDescriptor {
    Token key;                    // "opal:samplesPerPixel"
    std::string name;             // "Samples per pixel", for a label
    Value defaultValue;           // its type is the setting's type
    std::optional<double> min, max;   // for int and double settings
    std::vector<std::string> choices;  // for string settings with a fixed set of values
    std::string help;             // one line
};

}  // namespace opal::hd
