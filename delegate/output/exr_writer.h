// Scene-linear multi-layer OpenEXR output for compositing: one single-part file with one
// layer per AOV (Nuke's "layer.channel" names, see AovLayer), the working space's
// chromaticities and names in the header, and render settings as "opal/<key>" attributes.
#pragma once

#include "delegate/output/aov_layer.h"
#include "delegate/output/color_space_identity.h"

#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace opal {

enum class ExrPixelType { Half, Float };
enum class ExrCompression { Zip, Piz };

struct ExrOptions {
    ExrPixelType colorPixelType = ExrPixelType::Half;  // hd::AovFormat::Float32 is always float
    ExrCompression compression = ExrCompression::Zip;
};

using ExrMetadataValue = std::variant<std::string, float, int>;
// Render settings, written as header attributes "opal/<key>" ("samples" -> "opal/samples").
using ExrMetadata = std::vector<std::pair<std::string, ExrMetadataValue>>;

// Writes `layers` (all the same size; channel names unique across layers) to `file`,
// atomically. Header: `chromaticities` when the color space has known ones (else a
// warning: warnings may be null), `oiio:ColorSpace` = colorSpace.name (the OCIO name,
// which OpenImageIO reports on read), `colorInteropID` when known ("lin_ap1_scene").
// Throws opal::Error naming the file and the problem; `file` is then left as it was.
void writeExr(const std::filesystem::path& file, std::span<const AovLayer> layers,
              const ColorSpaceIdentity& colorSpace, const ExrMetadata& metadata,
              const ExrOptions& options, std::vector<std::string>* warnings);

}  // namespace opal
