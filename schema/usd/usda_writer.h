// Writes a Layer as canonical USDA, formatted the way usdcat writes it: 4-space
// indentation, metadata in parentheses after the prim/property header sorted by Sdf
// field name (comment first), dictionary entries sorted by key, arrays on one line,
// shortest round-trip numbers. Deterministic: write -> read -> write is byte-identical.
// Properties and children are written in model order. The model is validated first
// (names, paths, metadata keys and types, finite numbers): a layer that cannot be read
// back is never written; opal::Error says what and where in the model.
#pragma once

#include "schema/usd/usda_error.h"
#include "schema/usd/usda_layer.h"

#include <filesystem>
#include <string>

namespace opal::usda {

std::string writeUsda(const Layer& layer);

// Writes to a temporary file in the same directory, flushes it to disk and renames it
// over `path`, so readers never see a half-written layer. Errors name the path.
void writeUsdaFile(const std::filesystem::path& path, const Layer& layer);

}  // namespace opal::usda
