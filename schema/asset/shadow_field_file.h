// The light sidecar: a ShadowField in Opal's chunked container, kind `SFLD` (byte layout:
// schema/asset/LIGHTFIELD.md). Written atomically; read with every check of the container
// plus the field's own (shadow_field_checks.h). Errors name the file and the chunk.
#pragma once

#include "schema/asset/chunk_format.h"
#include "schema/asset/shadow_field.h"

#include <filesystem>

namespace opal {

inline constexpr FileKind kShadowFieldKind{"SFLD", {1, 0}};

namespace shadow_field_chunk {
inline constexpr ChunkTag kHeader = "HEAD";
inline constexpr ChunkTag kRadii = "RADI";
inline constexpr ChunkTag kMaps = "MAPS";
inline constexpr ChunkTag kBakeId = "BKID";
inline constexpr ChunkTag kViews = "VIEW";
}  // namespace shadow_field_chunk

// Values are stored as binary16 planes (array_codec.h): a writer that must read back what
// it wrote rounds them first with roundToHalfPlanes (the bake does).
void writeShadowFieldFile(const std::filesystem::path& path, const ShadowField& field);
ShadowField readShadowFieldFile(const std::filesystem::path& path);

}  // namespace opal
