// Reads Opal's USDA subset (schema/usd/SUBSET.md) into a Layer. Strict: anything
// outside the subset, and anything malformed, throws UsdaError
// "file:line:column: what was found, what was expected". Never crashes or hangs on
// any input: nesting depth and file size are bounded.
#pragma once

#include "schema/usd/usda_error.h"
#include "schema/usd/usda_layer.h"

#include <cstdint>
#include <filesystem>
#include <string_view>

namespace opal::usda {

// Prims nested deeper than this are rejected.
inline constexpr int kMaxPrimDepth = 128;
// Files larger than this are rejected before reading.
inline constexpr std::uintmax_t kMaxUsdaFileBytes = std::uintmax_t{1} << 31;

// `sourceName` is what messages call the text ("scene.usda").
Layer readUsda(std::string_view text, std::string_view sourceName);
// Messages name the path as given.
Layer readUsdaFile(const std::filesystem::path& path);

}  // namespace opal::usda
