// Reads a scene layer (the subset examples/SCENES.md documents), composed with its
// subLayers (layer_stack.h), into a Scene: walks the prims depth-first as a UsdStage
// traversal would, composes each prim's xformOps with its parent's, resolves material
// bindings down the hierarchy (the nearest binding wins unless an ancestor's is
// strongerThanDescendants), loads every baked asset once through an AssetCache, and checks
// every relationship target. Attributes with time samples are read at `timeCode`
// (schema/usd/time_samples.h).
#pragma once

#include "examples/scene/asset_cache.h"
#include "examples/scene/scene.h"

#include <filesystem>

namespace opal::scene {

// Throws opal::Error: the USDA reader's syntax errors, and usda::UsdaError with
// file:line:column naming the prim and property for everything outside the subset
// (unknown prim types, unknown attributes, wrong types, bad values, missing files,
// bindings to prims that are not Materials, ...).
Scene readScene(const std::filesystem::path& file, AssetCache& assets, double timeCode = 0.0);

}  // namespace opal::scene
