#include "delegate/commit_steps.h"

#include "delegate/hd/light_types.h"
#include "delegate/hd/mesh_material.h"
#include "schema/error.h"

#include <chrono>

namespace opal {

namespace {

// The prims of `types` that are T (the delegate made them: anything else is skipped).
template <typename T>
std::vector<T*> sprimsOf(const hd::RenderIndex& index, const std::vector<hd::Token>& types) {
    std::vector<T*> prims;
    for (const hd::Token& type : types)
        index.forEachSprim(type, [&](hd::Sprim& s) {
            if (auto* prim = dynamic_cast<T*>(&s)) prims.push_back(prim);
        });
    return prims;
}

// hd::meshMaterial, with the material prim's version (0 for the asset's default).
BoundMaterial resolveMaterial(const TranslucentMesh& mesh, const MaterialPrims& materials) {
    const hd::SdfPath& path = mesh.desc().material;
    const auto it = path.empty() ? materials.end() : materials.find(path);
    const OpalMaterial* prim = it == materials.end() ? nullptr : it->second;
    hd::MaterialDesc desc;
    try {
        desc = hd::meshMaterial(path, *mesh.desc().asset, prim ? &prim->desc() : nullptr);
    } catch (const Error& e) {
        throw Error("translucent mesh '" + mesh.id() + "': " + e.what());
    }
    return {path, prim ? prim->version() : 0, desc.subsurface, desc.specular, desc.specularRoughness};
}


}  // namespace

std::vector<OpalLight*> collectLightPrims(const hd::RenderIndex& index) {
    return sprimsOf<OpalLight>(index, hd::lightPrimTypes());
}

LightSources collectLights(const hd::RenderIndex& index, Frame& frame) {
    LightSources lights;
    for (const OpalLight* light : collectLightPrims(index)) {
        if (light->version() == 0) continue;
        LightSource source{light->version(), nullptr, nullptr, nullptr};
        if (light->isDome()) {
            source.environment = light->environment();
            frame.domes.push_back(
                {light->domeMap(), light->domeFromWorld(), light->domeScale(), light->desc().visibleToCamera});
        } else if (light->field()) {
            source.field = light->field();
            frame.lights.push_back(light->field()->highlight());
            frame.emitters.push_back(light->field());
        } else {
            source.analytic = &*light->analytic();
            frame.lights.push_back(*light->analytic());
        }
        lights.emplace(light->id(), std::move(source));
    }
    return lights;
}

MaterialPrims collectMaterials(const hd::RenderIndex& index) {
    MaterialPrims materials;
    for (const OpalMaterial* material : sprimsOf<const OpalMaterial>(index, {hd::PrimType::Material}))
        materials.emplace(material->id(), material);
    return materials;
}

std::vector<TranslucentMesh*> collectMeshes(const hd::RenderIndex& index) {
    std::vector<TranslucentMesh*> meshes;
    index.forEachRprim([&](hd::Rprim& r) {
        if (auto* mesh = dynamic_cast<TranslucentMesh*>(&r)) meshes.push_back(mesh);
    });
    return meshes;
}

bool geometryChanged(const std::vector<TranslucentMesh*>& meshes, const std::vector<const hd::Rprim*>& committed) {
    if (meshes.size() != committed.size()) return true;
    for (std::size_t i = 0; i < meshes.size(); ++i)
        if (meshes[i] != committed[i] || meshes[i]->geometryChanged()) return true;
    return false;
}

std::shared_ptr<const RayScene> buildRayScene(const std::vector<TranslucentMesh*>& meshes, CommitStats& stats) {
    const auto start = std::chrono::steady_clock::now();
    auto scene = std::make_shared<RayScene>();
    for (const TranslucentMesh* mesh : meshes) {
        if (!mesh->visible()) continue;
        try {
            scene->addMesh(mesh->desc().asset->mesh, mesh->desc().transform);
        } catch (const Error& e) {
            throw Error("translucent mesh '" + mesh->id() + "': " + e.what());
        }
    }
    scene->commit();
    ++stats.rayScenes;
    stats.rayScenesMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return scene;
}

void relightMeshes(const std::vector<TranslucentMesh*>& meshes, const LightSources& lights,
                   const MaterialPrims& materials, RelightOptions options, Frame& frame, CommitStats& stats,
                   std::vector<std::string>& warnings) {
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        TranslucentMesh& mesh = *meshes[i];
        if (!mesh.visible()) {
            mesh.hide();
            continue;
        }
        const BoundMaterial material = resolveMaterial(mesh, materials);
        mesh.updateIrradiance(lights, *frame.rays, options.raysRebuilt, stats);
        mesh.updateMaterial(material, stats, warnings);
        mesh.updateRadiance(options.reference, int(i), stats);
        frame.meshes.push_back(mesh.shading());
    }
}

}  // namespace opal
