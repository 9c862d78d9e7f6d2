// One AOV (arbitrary output variable) of a rendered frame and how it is named in a
// multi-layer EXR. The conventions (delegate/output/COLOR.md) are Nuke's: the beauty is the
// default layer (R, G, B, A without prefix); every other AOV is a layer "<aov>.<channel>".
#pragma once

#include "delegate/output/image.h"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace opal {

// How an AOV's channels are stored in an EXR.
enum class AovStorage {
    Color,  // radiance-like values: half by default, float on request
    Exact,  // depth and ids: always 32-bit float (half holds integers only up to 2048)
};

struct AovLayer {
    std::string name;                   // the AOV: "color", "subsurface", "depth", ...
    std::string exrLayer;               // "" for the default layer, else usually == name
    std::vector<std::string> channels;  // per image channel: "R", "X", "Z", "id", ...
    AovStorage storage = AovStorage::Color;
    Image image;  // image.channels() == channels.size()

    // "R" in the default layer, "<exrLayer>.<channel>" otherwise.
    std::string exrChannelName(std::size_t channel) const;
};

// Opal's AOVs (docs/ARCHITECTURE.md#image-formation; delegate/DELEGATE.md gives their values):
// color, subsurface, specular, irradiance, normal, depth, primId, alpha.
std::span<const std::string_view> standardAovNames();

// The standard layout of one of Opal's AOVs:
//   color        R G B [A]      default layer         Color
//   subsurface, specular, irradiance   <aov>.R/G/B    Color
//   normal       normal.X/Y/Z                         Color
//   depth        depth.Z                              Exact
//   primId       primId.id                            Exact (-1 where nothing was hit)
//   alpha        A              default layer         Color
// Throws opal::Error for an unknown name (listing the known ones) or an image whose
// channel count the AOV does not have.
AovLayer makeAovLayer(std::string_view name, Image image);

}  // namespace opal
