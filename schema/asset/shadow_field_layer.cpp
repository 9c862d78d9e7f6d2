#include "schema/asset/shadow_field_layer.h"

#include "schema/asset/asset_layer.h"
#include "schema/asset/bake_id.h"
#include "schema/error.h"
#include "schema/usd/usda_writer.h"

namespace opal {

using usda::Value;
namespace types = usda::types;

usda::Layer shadowFieldLayer(const std::string& primName, const std::string& fieldAssetPath,
                             std::optional<std::uint64_t> bakeId) {
    if (primName != assetNameFrom(primName))
        throw Error("light name '" + primName + "' is not a prim name (it would be '" + assetNameFrom(primName) + "')");
    usda::Prim prim;
    prim.specifier = usda::Specifier::Def;
    prim.typeName = std::string(kShadowFieldLightType);
    prim.name = primName;
    prim.addAttribute("inputs:color", Value::make<types::Color3f>({1.0f, 1.0f, 1.0f}));
    prim.addAttribute("inputs:exposure", Value::make<types::Float>(0.0f));
    prim.addAttribute("inputs:intensity", Value::make<types::Float>(1.0f));
    if (bakeId) prim.addAttribute(std::string(kBakeIdAttribute), Value::string(formatBakeId(*bakeId)), true);
    prim.addAttribute(std::string(kShadowFieldAttribute), Value::asset(fieldAssetPath), true);

    usda::Layer layer;
    layer.metadata.set("doc", Value::string("Opal shadow-field light: the source radiance field of '" + primName +
                                            "', radiance per RGB channel, lengths in mm"));
    layer.metadata.set("defaultPrim", Value::token(prim.name));
    layer.metadata.set("metersPerUnit", Value::make<types::Double>(0.001));
    layer.metadata.set("upAxis", Value::token("Y"));
    layer.addRootPrim(std::move(prim));
    return layer;
}

void writeShadowFieldLayer(const std::filesystem::path& usdaPath, const std::string& primName,
                           const std::string& fieldAssetPath, std::optional<std::uint64_t> bakeId) {
    usda::writeUsdaFile(usdaPath, shadowFieldLayer(primName, fieldAssetPath, bakeId));
}

}  // namespace opal
