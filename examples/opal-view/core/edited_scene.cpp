#include "examples/opal-view/core/edited_scene.h"

#include "schema/error.h"

namespace opal::view {
namespace {

template <class Prim>
Prim& find(std::map<hd::SdfPath, Prim>& prims, const hd::SdfPath& path, const char* what) {
    const auto it = prims.find(path);
    if (it == prims.end()) {
        std::string known;
        for (const auto& entry : prims) known += (known.empty() ? "<" : ", <") + entry.first + ">";
        throw Error(std::string("no ") + what + " <" + path + "> in the scene (" + what + "s: " +
                    (known.empty() ? "none" : known) + ")");
    }
    return it->second;
}

}  // namespace

void EditedScene::setMaterial(const hd::SdfPath& path, const hd::MaterialDesc& desc) {
    find(scene_.materials, path, "material").desc = desc;
    dirty_[path] |= hd::Dirty::Params | hd::Dirty::Material;
}

void EditedScene::setLight(const hd::SdfPath& path, const hd::LightDesc& desc) {
    find(scene_.lights, path, "light").desc = desc;
    dirty_[path] |= hd::Dirty::Params | hd::Dirty::Transform;
}

void EditedScene::setCamera(const hd::SdfPath& path, const hd::CameraDesc& desc) {
    find(scene_.cameras, path, "camera").desc = desc;
    dirty_[path] |= hd::Dirty::Params | hd::Dirty::Transform;
}

DirtyPrims EditedScene::takeChanges() {
    DirtyPrims changes;
    changes.swap(dirty_);
    return changes;
}

Imath::V3d lightPosition(const hd::LightDesc& light) {
    return {light.transform[3][0], light.transform[3][1], light.transform[3][2]};
}

hd::LightDesc movedLight(hd::LightDesc light, const Imath::V3d& position) {
    light.transform[3][0] = position.x;
    light.transform[3][1] = position.y;
    light.transform[3][2] = position.z;
    return light;
}

}  // namespace opal::view
