// Opal's AOVs (arbitrary output variables) and how each is described (Hydra's HdAovTokens and
// HdAovDescriptor): the one table the renderer, the render pass, the EXR layers, opal-render's
// --aov choices and delegate/DELEGATE.md derive from. Adding an AOV means one new row.
//
// Filtered AOVs are the filter-weighted average of a pixel's sub-pixel samples (radiometric
// values and coverage: colour is premultiplied by alpha). Nearest AOVs come from the one ray
// through the pixel centre: ids are never blended and a depth is a real surface's.
#pragma once

#include "delegate/hd/types.h"

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace opal::hd {

// How an AOV's channels are stored in files (the render buffers hold 32-bit floats).
enum class AovFormat {
    Float16,  // radiometric values: half in an EXR, float on request
    Float32,  // depth, and ids: half holds integers only up to 2048
};

enum class AovSampling {
    Filtered,  // the filter-weighted average over the pixel
    Nearest,   // the sample through the pixel centre
};

struct AovDescriptor {
    Token name;                             // "color", "depth", ...
    std::vector<std::string_view> channels;  // per channel: "R", "X", "Z", "id", ...
    AovFormat format = AovFormat::Float16;
    AovSampling sampling = AovSampling::Filtered;
    float clearValue = 0.0f;       // every channel of a pixel nothing covers yet
    std::string_view exrLayer;     // "" for the EXR's default layer (R, G, B, A)
    std::string_view meaning;      // one line, for documentation and help texts

    int channelCount() const { return int(channels.size()); }
};

// The rows, in the order AovId names them.
enum class AovId { Color, Subsurface, Specular, Emission, Irradiance, Normal, Depth, PrimId, Alpha };
inline constexpr std::size_t kAovCount = 9;

std::span<const AovDescriptor> aovTable();
const AovDescriptor& aovDescriptor(AovId id);
// nullptr for a name that is not one of Opal's AOVs.
const AovDescriptor* findAov(std::string_view name);
// The row's position; throws opal::Error for an unknown name, listing the known ones.
AovId aovId(std::string_view name);
// "color, subsurface, ..." for messages.
std::string aovNameList();

}  // namespace opal::hd
