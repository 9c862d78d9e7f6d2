// One AOV (arbitrary output variable) of a rendered frame and how it is named in a
// multi-layer EXR. The conventions (delegate/output/COLOR.md) are Nuke's: the beauty is the
// default layer (R, G, B, A without prefix); every other AOV is a layer "<aov>.<channel>".
// Names, channels and formats come from hd/aov.h's table.
#pragma once

#include "delegate/hd/aov.h"
#include "delegate/output/image.h"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace opal {

struct AovLayer {
    std::string name;                   // the AOV: "color", "subsurface", "depth", ...
    std::string exrLayer;               // "" for the default layer, else usually == name
    std::vector<std::string> channels;  // per image channel: "R", "X", "Z", "id", ...
    hd::AovFormat format = hd::AovFormat::Float16;  // Float16: half unless float is asked for
    Image image;  // image.channels() == channels.size()

    // "R" in the default layer, "<exrLayer>.<channel>" otherwise.
    std::string exrChannelName(std::size_t channel) const;
};

// One of Opal's AOVs as hd/aov.h's table describes it (channel names, EXR layer, format);
// color may come without its A (alpha then travels as its own AOV). Throws opal::Error for
// an unknown name (listing the known ones) or an image whose channel count the AOV does not
// have.
AovLayer makeAovLayer(std::string_view name, Image image);

}  // namespace opal
