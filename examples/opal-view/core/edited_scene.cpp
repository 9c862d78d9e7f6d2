#include "examples/opal-view/core/edited_scene.h"

#include "examples/opal-view/core/prim_path.h"
#include "schema/error.h"

namespace opal::view {
namespace {

constexpr hd::DirtyBits LightBits = hd::Dirty::Params | hd::Dirty::Transform;
constexpr hd::DirtyBits MaterialBits = hd::Dirty::Params | hd::Dirty::Material;

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

bool sameRgb(const Rgb& a, const Rgb& b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

}  // namespace

bool sameMaterial(const hd::MaterialDesc& a, const hd::MaterialDesc& b) {
    return sameRgb(a.subsurface.sigmaSPrime, b.subsurface.sigmaSPrime) && sameRgb(a.subsurface.sigmaA, b.subsurface.sigmaA) &&
           a.subsurface.eta == b.subsurface.eta && a.specular == b.specular && a.specularRoughness == b.specularRoughness;
}

bool sameLight(const hd::LightDesc& a, const hd::LightDesc& b) {
    return a.kind == b.kind && a.transform == b.transform && sameRgb(a.color, b.color) && a.intensity == b.intensity &&
           a.exposure == b.exposure && a.normalize == b.normalize && a.radius == b.radius &&
           a.treatAsPoint == b.treatAsPoint && a.shapingConeAngle == b.shapingConeAngle &&
           a.shapingConeSoftness == b.shapingConeSoftness && a.angle == b.angle && a.textureFile == b.textureFile &&
           a.textureColorSpace == b.textureColorSpace && a.visibleToCamera == b.visibleToCamera &&
           a.shadowField == b.shadowField && a.flicker.amplitude == b.flicker.amplitude &&
           a.flicker.frequency == b.flicker.frequency && a.flicker.seed == b.flicker.seed && a.time == b.time;
}

scene::Scene EditedScene::renderedScene() const {
    scene::Scene rendered = scene_;
    for (const hd::SdfPath& path : disabled_) rendered.lights.erase(path);
    return rendered;
}

void EditedScene::setMaterial(const hd::SdfPath& path, const hd::MaterialDesc& desc) {
    find(scene_.materials, path, "material").desc = desc;
    dirty_[path] |= MaterialBits;
    edited();
}

void EditedScene::setLight(const hd::SdfPath& path, const hd::LightDesc& desc) {
    find(scene_.lights, path, "light").desc = desc;
    dirty_[path] |= LightBits;
    edited();
}

void EditedScene::setCamera(const hd::SdfPath& path, const hd::CameraDesc& desc) {
    find(scene_.cameras, path, "camera").desc = desc;
    dirty_[path] |= hd::Dirty::Params | hd::Dirty::Transform;
}

void EditedScene::setTime(const scene::Scene* atTime, double timeCode) {
    for (const hd::SdfPath& id : atTime ? scene_.timeVarying : std::set<hd::SdfPath>{}) {
        const auto light = atTime->lights.find(id);
        const auto mine = scene_.lights.find(id);  // gone when the artist renamed or removed it
        if (light != atTime->lights.end() && mine != scene_.lights.end()) {
            mine->second.desc = light->second.desc;
            dirty_[id] |= LightBits;
        }
        const auto camera = atTime->cameras.find(id);
        if (camera != atTime->cameras.end() && scene_.cameras.count(id)) {
            scene_.cameras.at(id).desc = camera->second.desc;
            dirty_[id] |= hd::Dirty::Params | hd::Dirty::Transform;
        }
        const auto mesh = atTime->meshes.find(id);
        if (mesh != atTime->meshes.end() && scene_.meshes.count(id)) {
            scene_.meshes.at(id).desc.transform = mesh->second.desc.transform;
            dirty_[id] |= hd::Dirty::Transform;
        }
    }
    const double seconds = timeCode / scene_.timeCodesPerSecond;
    for (auto& [id, light] : scene_.lights)
        if (light.desc.flicker.amplitude > 0.0 && light.desc.time != seconds) {
            light.desc.time = seconds;
            dirty_[id] |= LightBits;
        }
    scene_.timeCode = timeCode;
}

void EditedScene::addLight(const hd::SdfPath& path, scene::SceneLight light) {
    requireNewPrimPath(scene_, path);
    scene_.lights[path] = std::move(light);
    dirty_[path] |= hd::Dirty::AllDirty;
    lightsChanged();
}

void EditedScene::removeLight(const hd::SdfPath& path) {
    find(scene_.lights, path, "light");
    scene_.lights.erase(path);
    disabled_.erase(path);
    dirty_.erase(path);
    lightsChanged();
}

void EditedScene::renameLight(const hd::SdfPath& from, const hd::SdfPath& to) {
    scene::SceneLight light = find(scene_.lights, from, "light");
    requireNewPrimPath(scene_, to);
    const bool disabled = disabled_.count(from) > 0;
    removeLight(from);
    addLight(to, std::move(light));
    if (disabled) disabled_.insert(to);
}

void EditedScene::setLightEnabled(const hd::SdfPath& path, bool enabled) {
    find(scene_.lights, path, "light");
    if (enabled == !disabled_.count(path)) return;
    if (enabled) {
        disabled_.erase(path);
        dirty_[path] |= hd::Dirty::AllDirty;  // inserted again
    } else {
        disabled_.insert(path);
        dirty_.erase(path);
    }
    lightsChanged();
}

EditState EditedScene::state() const { return {scene_.materials, scene_.lights, disabled_, revision_}; }

void EditedScene::restore(const EditState& state) {
    for (const auto& [path, material] : state.materials) {
        const auto now = scene_.materials.find(path);
        if (now != scene_.materials.end() && !sameMaterial(now->second.desc, material.desc)) dirty_[path] |= MaterialBits;
    }
    for (const auto& [path, light] : state.lights) {
        const auto now = scene_.lights.find(path);
        const bool enabledBefore = now != scene_.lights.end() && !disabled_.count(path);
        if (!enabledBefore) dirty_[path] |= hd::Dirty::AllDirty;  // inserted (again)
        else if (!sameLight(now->second.desc, light.desc)) dirty_[path] |= LightBits;
    }
    scene_.materials = state.materials;
    scene_.lights = state.lights;
    disabled_ = state.disabledLights;
    for (auto it = dirty_.begin(); it != dirty_.end();)
        it = scene_.lights.count(it->first) && disabled_.count(it->first) ? dirty_.erase(it) : std::next(it);
    revision_ = state.revision;
    lightsChanged_ = true;
}

DirtyPrims EditedScene::takeChanges() {
    DirtyPrims changes;
    changes.swap(dirty_);
    lightsChanged_ = false;
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
