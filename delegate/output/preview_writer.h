// 8-bit previews of display-referred images (DisplayTransform output) for people, not
// for compositing: PNG (RGB or RGBA) or JPEG (RGB), chosen by the file extension.
#pragma once

#include "delegate/output/image.h"

#include <cstdint>
#include <filesystem>

namespace opal {

// Display-referred value -> 8-bit code: clamp to [0, 1], scale by 255, round to nearest;
// NaN -> 0.
std::uint8_t quantizeToByte(float displayValue);

// Writes `displayReferred` (RGB or RGBA, values in [0, 1]) to `file` atomically.
// .png keeps alpha, stored unassociated as PNG requires (color is divided by alpha
// before quantization, pixels with zero alpha become black); .jpg/.jpeg drop alpha and keep
// the premultiplied color, i.e. the image over black. Throws opal::Error naming the file
// for any other extension, an unsupported channel count, or a failed write.
void writePreview(const std::filesystem::path& file, const Image& displayReferred);

}  // namespace opal
