#include "delegate/hd/mesh_material.h"

#include "schema/error.h"

namespace opal::hd {

MaterialDesc meshMaterial(const SdfPath& binding, const TranslucentAsset& asset, const MaterialDesc* bound) {
    if (binding.empty()) {
        MaterialDesc defaults;
        defaults.subsurface = asset.defaultMaterial;
        return defaults;
    }
    if (!bound) throw Error("its material '" + binding + "' is not a material prim of the render index");
    return *bound;
}

}  // namespace opal::hd
