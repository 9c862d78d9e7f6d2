#include "delegate/material_prim.h"

#include "schema/error.h"

#include <cmath>
#include <string>

namespace opal {

void OpalMaterial::sync(const hd::SceneDelegate& scene, hd::DirtyBits* dirtyBits) {
    if (*dirtyBits != hd::Dirty::Clean) {
        const hd::MaterialDesc desc = scene.material(id());
        validateMaterial(desc.subsurface, "material '" + id() + "'");
        if (!(desc.specularRoughness >= 0.0 && desc.specularRoughness <= 1.0))
            throw Error("material '" + id() + "': specular roughness " + std::to_string(desc.specularRoughness) +
                        " is not in [0, 1]");
        desc_ = desc;
        version_ = versions_.next();
    }
    *dirtyBits = hd::Dirty::Clean;
}

}  // namespace opal
