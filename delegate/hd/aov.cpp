#include "delegate/hd/aov.h"

#include "schema/error.h"

#include <limits>

namespace opal::hd {

namespace {

using enum AovFormat;
using enum AovSampling;

const float NoDepth = std::numeric_limits<float>::infinity();

const std::array<AovDescriptor, kAovCount> Table = {{
    {"color", {"R", "G", "B", "A"}, Float16, Filtered, 0.0f, "",
     "scene-linear radiance, premultiplied by A: subsurface + specular + emission, or the visible domes "
     "behind + emission"},
    {"subsurface", {"R", "G", "B"}, Float16, Filtered, 0.0f, "subsurface",
     "radiance scattered out of the surface: F_t(eta, n.w_o) times the relit vertex radiance"},
    {"specular", {"R", "G", "B"}, Float16, Filtered, 0.0f, "specular",
     "radiance of the GGX layer: analytic lights (shadowed) and the domes' reflection"},
    {"emission", {"R", "G", "B"}, Float16, Filtered, 0.0f, "emission",
     "radiance of the shadow-field lights' emitters seen in front of the surface (a flame)"},
    {"irradiance", {"R", "G", "B"}, Float16, Filtered, 0.0f, "irradiance",
     "irradiance E at the surface, interpolated from the vertices (W m^-2 per unit radiance)"},
    {"normal", {"X", "Y", "Z"}, Float16, Nearest, 0.0f, "normal", "world-space unit shading normal"},
    {"depth", {"Z"}, Float32, Nearest, NoDepth, "depth",
     "distance along the camera's view axis in scene units; infinity where nothing was hit"},
    {"primId", {"id"}, Float32, Nearest, -1.0f, "primId",
     "the translucent mesh's number, or a shadow-field light's after them (DELEGATE.md); -1 where "
     "nothing was hit"},
    {"alpha", {"A"}, Float16, Filtered, 0.0f, "", "coverage: the filter-weighted fraction of the pixel covered"},
}};

}  // namespace

std::span<const AovDescriptor> aovTable() { return Table; }

const AovDescriptor& aovDescriptor(AovId id) { return Table[std::size_t(id)]; }

const AovDescriptor* findAov(std::string_view name) {
    for (const AovDescriptor& row : Table)
        if (row.name == name) return &row;
    return nullptr;
}

AovId aovId(std::string_view name) {
    for (std::size_t i = 0; i < Table.size(); ++i)
        if (Table[i].name == name) return AovId(i);
    throw Error("unknown AOV '" + std::string(name) + "' (Opal renders " + aovNameList() + ")");
}

std::string aovNameList() {
    std::string list;
    for (const AovDescriptor& row : Table) list += (list.empty() ? "" : ", ") + row.name;
    return list;
}

}  // namespace opal::hd
