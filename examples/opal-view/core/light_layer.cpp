#include "examples/opal-view/core/light_layer.h"

#include "examples/scene/scene_lights.h"
#include "schema/asset/shadow_field_layer.h"
#include "schema/error.h"
#include "schema/usd/usda_error.h"

namespace opal::view {

hd::LightDesc readLightLayer(const std::filesystem::path& file) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error)) throw Error(file.string() + ": no such light layer");
    // The prim a scene would author to use it: a light referencing the layer.
    usda::Prim prim;
    prim.name = "Light";
    prim.typeName = std::string(kShadowFieldLightType);
    const std::filesystem::path absolute = std::filesystem::absolute(file).lexically_normal();
    prim.references.prepended.push_back({absolute.string(), "", {}});
    scene::PrimReader reader(prim, "/Light");
    try {
        return scene::referencedLight(reader, absolute, 0.0).desc;
    } catch (const usda::UsdaError& e) {
        if (e.where().file) throw;  // inside the light layer: its own place
        throw Error(file.string() + ": not a baked light layer (no " + std::string(kShadowFieldLightType) +
                    " prim as its defaultPrim)");
    }
}

}  // namespace opal::view
