// The USDA half of a baked asset (docs/ARCHITECTURE.md#asset): a root Mesh prim with the render
// mesh and the applied OpalSubsurfaceAPI (schema/usd/opal.usda): default material, units,
// editable range, the PCA profile basis, and the asset path of the sidecar; bake settings
// in the prim's customData. readAsset() reads both halves and checks they belong together.
#pragma once

#include "schema/asset/translucent_asset.h"
#include "schema/usd/usda_layer.h"

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace opal {

// The attributes primToAsset reads of an asset's prim (besides its type and API schema).
std::span<const std::string_view> assetPrimAttributes();

inline constexpr std::string_view kSubsurfaceApi = "OpalSubsurfaceAPI";
// The bake's identifier (bake_id.h), written when asset.bake.identifier is set.
inline constexpr std::string_view kBakeIdAttribute = "opal:bakeId";

// An asset's name is the name of its prim: `text` with every character that is not a
// letter, digit or '_' replaced by '_', and '_' in front of a leading digit or an empty
// name ("stanford-bunny" -> "stanford_bunny"). The bake names assets with it, so that the
// sidecar, which records the name, and the layer agree.
std::string assetNameFrom(std::string_view text);

// `sidecarAssetPath` is written as given (relative to the layer, e.g. "./candle.opal").
// Throws opal::Error unless asset.name is its own assetNameFrom().
usda::Layer assetToLayer(const TranslucentAsset& asset, const std::string& sidecarAssetPath);

// Writes the layer atomically.
void writeAssetLayer(const std::filesystem::path& usdaPath, const TranslucentAsset& asset,
                     const std::string& sidecarAssetPath);

// Fills the USDA-side fields of `asset` from a prim with OpalSubsurfaceAPI (mesh, material,
// units, range, basis, bake settings) and returns the sidecar asset path as authored.
// Throws opal::Error with file:line:column of the offending attribute.
std::string primToAsset(const usda::Prim& prim, TranslucentAsset& asset);

// Reads `usdaPath` (its default prim, else its first root prim), then the sidecar it names
// (resolved relative to the layer's directory), validating both and their agreement: the
// bake identifiers of layer and sidecar must be equal ("sidecar and layer are not from the
// same bake", naming both files and both identifiers), and so must what the sidecar's
// header records of the layer. An asset whose halves both lack an identifier (baked before
// Opal recorded one) loads, and adds one warning to `warnings` saying to re-bake it.
TranslucentAsset readAsset(const std::filesystem::path& usdaPath, std::vector<std::string>* warnings = nullptr);

// The same for a prim that applies OpalSubsurfaceAPI wherever it stands (a scene's prim
// composed from an over-layer, say): its sidecar is resolved relative to the directory of
// `anchorFile`, the layer its asset paths are anchored at, which messages name.
TranslucentAsset readAsset(const usda::Prim& prim, const std::filesystem::path& anchorFile,
                           std::vector<std::string>* warnings = nullptr);

}  // namespace opal
