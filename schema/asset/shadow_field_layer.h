// The USDA half of a light asset: one root `OpalShadowFieldLight` prim (schema/usd/opal.usda)
// whose `opal:field` names the light sidecar (shadow_field_file.h), with LightAPI's
// intensity 1, color (1, 1, 1) and exposure 0, so that by default the light emits the
// baked radiance (L = color x intensity x 2^exposure x field). The layer is in millimetres
// (metersPerUnit 0.001), +Y up, as the field's frame.
#pragma once

#include "schema/usd/usda_layer.h"

#include <filesystem>
#include <optional>
#include <string>

namespace opal {

inline constexpr std::string_view kShadowFieldLightType = "OpalShadowFieldLight";
inline constexpr std::string_view kShadowFieldAttribute = "opal:field";

// `primName` must be a prim name (assetNameFrom). `fieldAssetPath` is written as given,
// relative to the layer ("./flame.0123456789abcdef.field"). `bakeId`, when set, is
// written as `uniform string opal:bakeId` (16 hex digits), as the asset bake does.
usda::Layer shadowFieldLayer(const std::string& primName, const std::string& fieldAssetPath,
                             std::optional<std::uint64_t> bakeId);
// Writes it atomically (schema/usd/atomic_file.h).
void writeShadowFieldLayer(const std::filesystem::path& usdaPath, const std::string& primName,
                           const std::string& fieldAssetPath, std::optional<std::uint64_t> bakeId);

}  // namespace opal
