#include "examples/opal-view/core/scene_document.h"

#include "examples/opal-view/core/new_light.h"
#include "examples/opal-view/core/prim_path.h"
#include "examples/opal-view/core/scene_bounds.h"
#include "examples/scene/render_setup.h"
#include "examples/scene/scene_reader.h"
#include "schema/asset/asset_layer.h"
#include "schema/error.h"
#include "schema/usd/usda_reader.h"

#include <cmath>

namespace opal::view {
namespace {

scene::Scene stagedAsset(const std::filesystem::path& file, scene::AssetCache& assets) {
    scene::Scene scene;
    scene.file = file;
    hd::MeshDesc mesh;
    mesh.asset = assets.load(file);
    scene.metersPerUnit = 0.001 / mesh.asset->unitsPerMm;
    scene.meshes["/" + mesh.asset->name] = {mesh, file, {}};
    for (const std::string& warning : assets.takeWarnings()) scene.warnings.push_back(warning);
    scene.lights[KeyLightPath] = newLight(NewLightKind::Point, sceneBounds(scene));
    return scene;
}

bool usesViewerRoot(const scene::Scene& scene) {
    const auto under = [](const auto& prims) {
        for (const auto& entry : prims)
            if (entry.first == ViewerRoot || entry.first.starts_with(ViewerRoot + "/")) return true;
        return false;
    };
    return under(scene.meshes) || under(scene.materials) || under(scene.lights) || under(scene.cameras);
}

// Every unbound mesh gets its own material prim holding the asset's default.
void bindEditableMaterials(scene::Scene& scene) {
    for (auto& [path, mesh] : scene.meshes) {
        if (!mesh.desc.material.empty()) continue;
        const hd::SdfPath material = ViewerRoot + "/Materials/" + primName(path);
        hd::MaterialDesc desc;
        desc.subsurface = mesh.desc.asset->defaultMaterial;
        scene.materials[material] = {desc, {}};
        mesh.desc.material = material;
    }
}

// The camera the scene renders through (opal-render's choice), or its first one.
std::optional<hd::SdfPath> chooseSceneCamera(const scene::Scene& scene) {
    if (scene.cameras.empty()) return std::nullopt;
    try {
        return scene::chooseRenderSetup(scene, {}).camera;
    } catch (const Error&) {  // several cameras and no RenderSettings: the viewer may pick
        return scene.cameras.begin()->first;
    }
}

}  // namespace

bool isAssetLayer(const std::filesystem::path& file) {
    const usda::Layer layer = usda::readUsdaFile(file);
    std::string defaultPath = "/";  // appended, not "/" + name: GCC 12 warns (-Wrestrict) wrongly
    defaultPath += layer.defaultPrim();
    const usda::Prim* prim = layer.defaultPrim().empty() ? nullptr : layer.findPrim(defaultPath);
    if (!prim && !layer.rootPrims.empty()) prim = &layer.rootPrims.front();
    return prim && prim->hasApiSchema(kSubsurfaceApi);
}

SceneDocument loadDocument(const std::filesystem::path& file, scene::AssetCache& assets) {
    SceneDocument document;
    document.assetOnly = isAssetLayer(file);
    document.scene = document.assetOnly ? stagedAsset(file, assets) : scene::readScene(file, assets);
    if (document.scene.meshes.empty())
        throw Error(file.string() + ": the scene has no translucent mesh (a prim referencing a baked asset, or a Mesh applying OpalSubsurfaceAPI) to look at");
    if (!document.assetOnly && usesViewerRoot(document.scene))
        throw Error(file.string() + ": the scene has prims under <" + ViewerRoot + ">, which the viewer needs for its own");
    document.sceneCamera = chooseSceneCamera(document.scene);
    bindEditableMaterials(document.scene);
    return document;
}

}  // namespace opal::view
