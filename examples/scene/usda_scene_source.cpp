#include "examples/scene/usda_scene_source.h"

#include "examples/scene/scene_reader.h"

#include "schema/error.h"
#include "schema/usd/usda_error.h"

#include <cmath>

namespace opal::scene {
namespace {

template <class Prim>
const Prim& lookUp(const std::map<hd::SdfPath, Prim>& prims, const hd::SdfPath& id, const Scene& scene,
                   const char* what) {
    const auto it = prims.find(id);
    if (it == prims.end()) throw Error(scene.file.string() + ": no " + what + " prim <" + id + "> in the scene");
    return it->second;
}

template <class Insert>
void insertAt(const usda::SourceLocation& where, const hd::SdfPath& id, Insert&& insert) {
    try {
        insert();
    } catch (const usda::UsdaError&) {
        throw;
    } catch (const Error& e) {
        throw usda::UsdaError(where, "<" + id + ">: " + e.what());
    }
}

}  // namespace

void UsdaSceneSource::populate(hd::RenderIndex& index) const {
    // Map entries, not structured bindings: clang 14 cannot capture bindings in lambdas.
    for (const auto& entry : scene_.materials)
        insertAt(entry.second.where, entry.first,
                 [&] { index.insertSprim(hd::PrimType::Material, *this, entry.first); });
    for (const auto& entry : scene_.cameras)
        insertAt(entry.second.where, entry.first, [&] { index.insertSprim(hd::PrimType::Camera, *this, entry.first); });
    for (const auto& entry : scene_.lights)
        insertAt(entry.second.where, entry.first,
                 [&] { index.insertSprim(entry.second.primType, *this, entry.first); });
    for (const auto& entry : scene_.meshes)
        insertAt(entry.second.where, entry.first,
                 [&] { index.insertRprim(hd::PrimType::TranslucentMesh, *this, entry.first); });
}

hd::MeshDesc UsdaSceneSource::mesh(const hd::SdfPath& id) const {
    return lookUp(scene_.meshes, id, scene_, "mesh").desc;
}

hd::MaterialDesc UsdaSceneSource::material(const hd::SdfPath& id) const {
    return lookUp(scene_.materials, id, scene_, "Material").desc;
}

hd::LightDesc UsdaSceneSource::light(const hd::SdfPath& id) const {
    hd::LightDesc desc = lookUp(scene_.lights, id, scene_, "light").desc;
    desc.time = time_;
    return desc;
}

void UsdaSceneSource::setTime(double seconds, hd::RenderIndex& index, AssetCache& assets) {
    if (!std::isfinite(seconds)) throw Error(scene_.file.string() + ": the scene time is not finite");
    if (seconds == time_) return;
    if (!scene_.timeVarying.empty())
        takeTimeVarying(readScene(scene_.file, assets, seconds * scene_.timeCodesPerSecond), index);
    time_ = seconds;
    for (const auto& [id, light] : scene_.lights)
        if (light.desc.kind == hd::LightKind::ShadowField && light.desc.flicker.amplitude > 0.0)
            index.changeTracker().markDirty(id, hd::Dirty::Params);
}

// Only the time-varying prims are taken from the scene read at the new time: a host's
// edits to the others (a viewer's, opal-render's --material) stay.
void UsdaSceneSource::takeTimeVarying(Scene atTime, hd::RenderIndex& index) {
    hd::ChangeTracker& tracker = index.changeTracker();
    for (const hd::SdfPath& id : scene_.timeVarying) {
        if (auto light = atTime.lights.find(id); light != atTime.lights.end()) {
            scene_.lights.at(id).desc = std::move(light->second.desc);
            tracker.markDirty(id, hd::Dirty::Params | hd::Dirty::Transform);
        } else if (auto camera = atTime.cameras.find(id); camera != atTime.cameras.end()) {
            scene_.cameras.at(id).desc = std::move(camera->second.desc);
            tracker.markDirty(id, hd::Dirty::Params | hd::Dirty::Transform);
        } else if (auto mesh = atTime.meshes.find(id); mesh != atTime.meshes.end()) {
            scene_.meshes.at(id).desc.transform = mesh->second.desc.transform;
            tracker.markDirty(id, hd::Dirty::Transform);
        }
    }
    scene_.timeCode = atTime.timeCode;
}

hd::CameraDesc UsdaSceneSource::camera(const hd::SdfPath& id) const {
    return lookUp(scene_.cameras, id, scene_, "Camera").desc;
}

}  // namespace opal::scene
