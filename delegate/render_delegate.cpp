#include "delegate/render_delegate.h"

#include "delegate/camera.h"
#include "delegate/hd/render_index.h"
#include "delegate/light.h"
#include "delegate/material_prim.h"
#include "delegate/render_pass.h"
#include "delegate/translucent_mesh.h"
#include "schema/error.h"

#include <chrono>
#include <climits>

namespace opal {

namespace {

const std::string StatsPrefix = "opal:stats:";

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

int saturated(std::uint64_t n) { return n > std::uint64_t(INT_MAX) ? INT_MAX : int(n); }

const std::vector<hd::Token>& lightTypes() {
    static const std::vector<hd::Token> types = {hd::PrimType::SphereLight, hd::PrimType::DistantLight,
                                                 hd::PrimType::DomeLight};
    return types;
}

BoundMaterial resolveMaterial(const TranslucentMesh& mesh, const std::map<hd::SdfPath, const OpalMaterial*>& materials) {
    BoundMaterial bound;
    const hd::SdfPath& path = mesh.desc().material;
    if (path.empty()) {
        bound.subsurface = mesh.desc().asset->defaultMaterial;
        const hd::MaterialDesc defaults;
        bound.specular = defaults.specular;
        bound.roughness = defaults.specularRoughness;
        return bound;
    }
    const auto it = materials.find(path);
    if (it == materials.end())
        throw Error("translucent mesh '" + mesh.id() + "': its material '" + path +
                    "' is not a material prim of the render index");
    bound.path = path;
    bound.version = it->second->version();
    bound.subsurface = it->second->desc().subsurface;
    bound.specular = it->second->desc().specular;
    bound.roughness = it->second->desc().specularRoughness;
    return bound;
}

}  // namespace

OpalRenderDelegate::OpalRenderDelegate(const std::map<hd::Token, hd::Value>& settings) {
    for (const auto& [key, value] : settings) setRenderSetting(key, value);
    textures_.reset(settings_.ocioConfig);
    texturesConfig_ = settings_.ocioConfig;
}

OpalRenderDelegate::~OpalRenderDelegate() = default;

std::vector<hd::Token> OpalRenderDelegate::supportedRprimTypes() const { return {hd::PrimType::TranslucentMesh}; }

std::vector<hd::Token> OpalRenderDelegate::supportedSprimTypes() const {
    std::vector<hd::Token> types = {hd::PrimType::Camera, hd::PrimType::Material};
    types.insert(types.end(), lightTypes().begin(), lightTypes().end());
    return types;
}

std::vector<hd::Token> OpalRenderDelegate::supportedBprimTypes() const { return {hd::PrimType::RenderBuffer}; }

std::unique_ptr<hd::Rprim> OpalRenderDelegate::createRprim(const hd::Token& type, const hd::SdfPath& id) {
    if (type == hd::PrimType::TranslucentMesh) return std::make_unique<TranslucentMesh>(id);
    return nullptr;
}

std::unique_ptr<hd::Sprim> OpalRenderDelegate::createSprim(const hd::Token& type, const hd::SdfPath& id) {
    if (type == hd::PrimType::Camera) return std::make_unique<OpalCamera>(id);
    if (type == hd::PrimType::Material) return std::make_unique<OpalMaterial>(id, versions_);
    for (const hd::Token& light : lightTypes())
        if (type == light) return std::make_unique<OpalLight>(id, type, textures_, versions_);
    return nullptr;
}

std::unique_ptr<hd::Bprim> OpalRenderDelegate::createBprim(const hd::Token& type, const hd::SdfPath& id) {
    if (type == hd::PrimType::RenderBuffer) return std::make_unique<hd::RenderBuffer>(id);
    return nullptr;
}

std::vector<hd::Token> OpalRenderDelegate::statisticNames() {
    std::vector<hd::Token> names;
    for (const char* name : {"commitMs", "rayScenesMs", "irradianceMs", "productsMs", "materialMs", "referenceMs",
                             "renderMs", "commits", "rayScenes", "lightEvaluations", "irradianceProducts",
                             "materialUpdates", "referenceGathers"})
        names.push_back(StatsPrefix + name);
    return names;
}

void OpalRenderDelegate::setRenderSetting(const hd::Token& key, const hd::Value& value) {
    if (key.rfind(StatsPrefix, 0) == 0)
        throw Error("Opal render delegate: render setting '" + key + "' is a read-only statistic");
    const bool commitAffecting = key == "opal:reference" || key == "opal:ocioConfig";
    if (settings_.set(key, value) && commitAffecting) ++settingsVersion_;
}

hd::Value OpalRenderDelegate::renderSetting(const hd::Token& key) const {
    if (key.rfind(StatsPrefix, 0) != 0) return settings_.get(key);
    const std::string name = key.substr(StatsPrefix.size());
    if (name == "commitMs") return lastCommit_.totalMs;
    if (name == "rayScenesMs") return lastCommit_.rayScenesMs;
    if (name == "irradianceMs") return lastCommit_.irradianceMs;
    if (name == "productsMs") return lastCommit_.productsMs;
    if (name == "materialMs") return lastCommit_.materialMs;
    if (name == "referenceMs") return lastCommit_.referenceMs;
    if (name == "renderMs") return lastRenderMs_;
    if (name == "commits") return saturated(commits_);
    if (name == "rayScenes") return saturated(totals_.rayScenes);
    if (name == "lightEvaluations") return saturated(totals_.lightEvaluations);
    if (name == "irradianceProducts") return saturated(totals_.irradianceProducts);
    if (name == "materialUpdates") return saturated(totals_.materialUpdates);
    if (name == "referenceGathers") return saturated(totals_.referenceGathers);
    std::string known;
    for (const hd::Token& n : statisticNames()) known += (known.empty() ? "" : ", ") + n;
    throw Error("Opal render delegate: unknown statistic '" + key + "' (known: " + known + ")");
}

std::map<hd::Token, hd::Value> OpalRenderDelegate::renderSettings() const { return settings_.all(); }

std::unique_ptr<hd::RenderPass> OpalRenderDelegate::createRenderPass(hd::RenderIndex& index) {
    return std::make_unique<OpalRenderPass>(*this, index);
}

std::vector<std::string> OpalRenderDelegate::takeWarnings() {
    std::vector<std::string> warnings;
    warnings.swap(warnings_);
    return warnings;
}

std::shared_ptr<const Frame> OpalRenderDelegate::frame(hd::RenderIndex& index) {
    if (!frame_ || &index != index_ || settingsVersion_ != committedSettingsVersion_) commitResources(index);
    return frame_;
}

void OpalRenderDelegate::commitResources(hd::RenderIndex& index) {
    const auto start = std::chrono::steady_clock::now();
    CommitStats stats;
    if (&index != index_) {  // another index: nothing committed before applies
        index_ = &index;
        frame_.reset();
        committedMeshes_.clear();
    }
    if (settings_.ocioConfig != texturesConfig_) {
        textures_.reset(settings_.ocioConfig);
        texturesConfig_ = settings_.ocioConfig;
        for (const hd::Token& type : lightTypes())
            index.forEachSprim(type, [](hd::Sprim& s) {
                if (auto* light = dynamic_cast<OpalLight*>(&s)) light->reloadTexture();
            });
    }

    // Lights (a sync that failed leaves version 0: such a light is not there yet).
    LightSources lights;
    auto frame = std::make_shared<Frame>();
    for (const hd::Token& type : lightTypes())
        index.forEachSprim(type, [&](hd::Sprim& s) {
            const auto* light = dynamic_cast<const OpalLight*>(&s);
            if (!light || light->version() == 0) return;
            LightSource source{light->version(), nullptr, nullptr};
            if (light->isDome()) {
                source.environment = light->environment();
                frame->domes.push_back(
                    {light->domeMap(), light->domeFromWorld(), light->domeScale(), light->desc().visibleToCamera});
            } else {
                source.analytic = &*light->analytic();
                frame->lights.push_back(*light->analytic());
            }
            lights.emplace(light->id(), std::move(source));
        });
    std::map<hd::SdfPath, const OpalMaterial*> materials;
    index.forEachSprim(hd::PrimType::Material, [&](hd::Sprim& s) {
        if (const auto* material = dynamic_cast<const OpalMaterial*>(&s)) materials.emplace(material->id(), material);
    });
    std::vector<TranslucentMesh*> meshes;
    index.forEachRprim([&](hd::Rprim& r) {
        if (auto* mesh = dynamic_cast<TranslucentMesh*>(&r)) meshes.push_back(mesh);
    });

    // The Embree scene: rebuilt when any mesh was added, removed, moved, shown or hidden.
    bool rebuild = !frame_ || meshes.size() != committedMeshes_.size();
    for (std::size_t i = 0; i < meshes.size() && !rebuild; ++i)
        rebuild = meshes[i] != committedMeshes_[i] || meshes[i]->geometryChanged();
    std::shared_ptr<const RayScene> rays = frame_ ? frame_->rays : nullptr;
    if (rebuild) {
        const auto built = std::chrono::steady_clock::now();
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
        rays = std::move(scene);
        ++stats.rayScenes;
        stats.rayScenesMs = millisecondsSince(built);
    }
    frame->rays = rays;

    // Each mesh: its lights' E, its material, its radiance (only what changed).
    std::vector<hd::SdfPath> paths;
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        TranslucentMesh& mesh = *meshes[i];
        paths.push_back(mesh.id());
        if (!mesh.visible()) {
            mesh.hide();
            continue;
        }
        const BoundMaterial material = resolveMaterial(mesh, materials);
        mesh.updateIrradiance(lights, *rays, rebuild, stats);
        mesh.updateMaterial(material, stats, warnings_);
        mesh.updateRadiance(settings_.reference, int(i), stats);
        frame->meshes.push_back(mesh.shading());
    }

    for (TranslucentMesh* mesh : meshes) mesh->markCommitted();
    committedMeshes_.assign(meshes.begin(), meshes.end());
    meshPaths_ = std::move(paths);
    frame_ = std::move(frame);
    committedSettingsVersion_ = settingsVersion_;
    stats.totalMs = millisecondsSince(start);
    lastCommit_ = stats;
    totals_ += stats;
    ++commits_;
}

}  // namespace opal
