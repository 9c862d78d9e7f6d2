#include "delegate/translucent_mesh.h"

#include "delegate/relight/reference_gather.h"
#include "delegate/relight/stopwatch.h"
#include "schema/error.h"

#include <algorithm>

namespace opal {

namespace {

// What the renderer needs beyond what RelightEngine checks: per-vertex weights and normals
// that match the render mesh.
void checkShadeable(const TranslucentAsset& asset, const hd::SdfPath& id) {
    const std::size_t vertices = asset.mesh.points.size();
    const auto fail = [&](const std::string& what) {
        throw Error("translucent mesh '" + id + "': asset '" + asset.name + "': " + what);
    };
    if (vertices == 0 || asset.mesh.faceVertexCounts.empty()) fail("the render mesh is empty");
    if (asset.vertexWeights.offsets.size() != vertices + 1)
        fail(std::to_string(asset.vertexWeights.offsets.size()) + " vertex weight offsets for " +
             std::to_string(vertices) + " render-mesh vertices (expected vertices + 1)");
    if (!asset.mesh.normals.empty() && asset.mesh.normals.size() != vertices)
        fail(std::to_string(asset.mesh.normals.size()) + " normals for " + std::to_string(vertices) + " vertices");
}

}  // namespace

void TranslucentMesh::fail(const std::string& what) const { throw Error("translucent mesh '" + id() + "': " + what); }

void TranslucentMesh::sync(const hd::SceneDelegate& scene, hd::DirtyBits* dirtyBits) {
    namespace Dirty = hd::Dirty;
    const hd::DirtyBits bits = *dirtyBits;
    if (bits & (Dirty::Topology | Dirty::Transform | Dirty::Material | Dirty::Visibility)) {
        const hd::MeshDesc d = scene.mesh(id());
        // Validate everything first: a failed sync leaves the mesh as it was.
        if (bits & Dirty::Topology) {
            if (!d.asset) fail("the scene gave no asset");
            checkShadeable(*d.asset, id());
        }
        if (bits & Dirty::Transform) {
            try {
                rotationOf(d.transform, "transform");
            } catch (const Error& e) {
                fail(e.what());
            }
        }
        if (bits & Dirty::Topology) {
            desc_.asset = d.asset;
            topologyChanged_ = true;
        }
        if ((bits & Dirty::Transform) && (d.transform != desc_.transform || topologyChanged_)) {
            desc_.transform = d.transform;
            transformChanged_ = true;
        }
        if (bits & Dirty::Material) desc_.material = d.material;
        if ((bits & Dirty::Visibility) && d.visible != desc_.visible) {
            desc_.visible = d.visible;
            visibilityChanged_ = true;
        }
    }
    *dirtyBits = Dirty::Clean;
}

void TranslucentMesh::addLight(const hd::SdfPath& light, const LightSource& source, const RayScene& rays,
                               CommitStats& stats) {
    try {
        if (source.analytic)
            irradiance_->setLight(light, *source.analytic, rays);
        else if (source.field)
            irradiance_->setLight(light, source.field, rays);
        else
            irradiance_->setLight(light, source.environment);
    } catch (const Error& e) {
        fail("light '" + light + "': " + e.what());
    }
    stats.lightMomentsMs += irradiance_->lastUpdate().momentsMs;
    appliedLights_[light] = source.version;
    ++stats.lightEvaluations;
}

void TranslucentMesh::updateIrradiance(const LightSources& lights, const RayScene& rays, bool raysRebuilt,
                                       CommitStats& stats) {
    const Stopwatch clock;
    if (topologyChanged_ || !engine_) {
        try {
            engine_ = std::make_unique<RelightEngine>(desc_.asset);
        } catch (const Error& e) {
            fail(e.what());
        }
        engineHasMaterial_ = false;
        engineMoments_ = 0;
        relightInFull_ = true;
    }
    if (relightInFull_ || !irradiance_) {
        try {
            irradiance_ = std::make_unique<MeshIrradiance>(desc_.asset, desc_.transform);
        } catch (const Error& e) {
            fail(e.what());
        }
        appliedLights_.clear();
        for (const auto& [light, source] : lights) addLight(light, source, rays, stats);
        relightInFull_ = false;
        ++momentsVersion_;
        stats.irradianceMs += clock.ms();
        return;
    }
    bool changed = false;
    // Lights gone or changed leave first, so that the bulk updates below skip them.
    std::size_t shadowedKept = 0;
    for (auto it = appliedLights_.begin(); it != appliedLights_.end();) {
        const auto light = lights.find(it->first);
        if (light == lights.end() || light->second.version != it->second) {
            irradiance_->removeLight(it->first);
            it = appliedLights_.erase(it);
            changed = true;
        } else {
            if (light->second.shadowed()) ++shadowedKept;
            ++it;
        }
    }
    if (transformChanged_) {
        try {
            irradiance_->setTransform(desc_.transform, rays);  // samples moved: every light
        } catch (const Error& e) {
            fail(e.what());
        }
        stats.lightEvaluations += appliedLights_.size();
        changed = true;
    } else if (raysRebuilt && shadowedKept > 0) {
        irradiance_->updateShadows(rays);  // occluders moved: the shadowed lights
        stats.lightEvaluations += shadowedKept;
        changed = true;
    }
    for (const auto& [light, source] : lights)
        if (!appliedLights_.count(light)) {
            addLight(light, source, rays, stats);
            changed = true;
        }
    if (changed) {
        ++momentsVersion_;
        stats.irradianceMs += clock.ms();
    }
}

void TranslucentMesh::updateMaterial(const BoundMaterial& material, CommitStats& stats,
                                     std::vector<std::string>& warnings) {
    if (engineHasMaterial_ && material.path == material_.path && material.version == material_.version) return;
    const Stopwatch clock;
    std::vector<std::string> clamped;
    try {
        clamped = engine_->setMaterial(material.subsurface);
    } catch (const Error& e) {
        fail("material '" + (material.path.empty() ? "(the asset's default)" : material.path) + "': " + e.what());
    }
    for (const std::string& w : clamped)
        warnings.push_back("translucent mesh '" + id() + "', material '" +
                           (material.path.empty() ? "(the asset's default)" : material.path) + "': " + w);
    material_ = material;
    engineHasMaterial_ = true;
    ++materialVersion_;
    ++stats.materialUpdates;
    stats.materialMs += clock.ms();
}

void TranslucentMesh::updateRadiance(bool reference, int primId, CommitStats& stats) {
    const OutputKey key{reference, momentsVersion_, materialVersion_, primId};
    if (shading_ && key == output_) return;
    // The per-vertex buffers are shared, not copied: radiance with the engine (which never
    // changes a buffer a frame holds), irradiance across commits with the same lights and eta.
    auto shading = std::make_shared<MeshShading>();
    shading->asset = desc_.asset;
    shading->normalToWorld = Imath::M33f(rotationOf(desc_.transform, "transform"));
    shading->specular = material_.specular;
    shading->roughness = material_.roughness;
    shading->primId = primId;
    if (!reference) {
        if (engineMoments_ != momentsVersion_) {
            const Stopwatch clock;
            engine_->setIrradiance(irradiance_->moments());
            engineMoments_ = momentsVersion_;
            ++stats.irradianceProducts;
            stats.productsMs += clock.ms();
        }
        const Stopwatch clock;
        stats.projectedValues += engine_->radianceNoise().values;
        stats.deepestProjected = std::min(stats.deepestProjected, engine_->radianceNoise().deepest);
        stats.projectedIrradiance += engine_->irradianceNoise().values;
        stats.deepestIrradiance = std::min(stats.deepestIrradiance, engine_->irradianceNoise().deepest);
        shading->vertexRadiance = engine_->sharedVertexRadiance();
        shading->eta = engine_->material().eta;
        vertexIrradiance_ = engine_->sharedVertexIrradiance();  // gathered again only after E changed
        stats.materialMs += clock.ms();
    } else {
        // Ground truth: the same lights' true E (F_t(eta, .) per light, not its moment fit;
        // domes integrated over the hemisphere, not through the baked vectors), the exact
        // dipole over every pair of samples, the material as requested.
        const Stopwatch clock;
        const Material& m = material_.subsurface;
        std::vector<float> exact, gathered;
        try {
            exact = irradiance_->referenceIrradiance(m.eta);
            gathered = referenceGather(*desc_.asset, m, exact);
        } catch (const Error& e) {
            fail(e.what());
        }
        shading->vertexRadiance = std::make_shared<const std::vector<float>>(engine_->toVertices(gathered));
        vertexIrradiance_ = std::make_shared<const std::vector<float>>(engine_->toVertices(exact));
        shading->eta = m.eta;
        ++stats.referenceGathers;
        stats.referenceMs += clock.ms();
    }
    shading->vertexIrradiance = vertexIrradiance_;
    shading_ = std::move(shading);
    output_ = key;
}

void TranslucentMesh::hide() {
    if (topologyChanged_) {  // the old asset's state is of no further use
        engine_.reset();
        irradiance_.reset();
        appliedLights_.clear();
        engineHasMaterial_ = false;
    }
    shading_.reset();
    vertexIrradiance_.reset();
    relightInFull_ = true;
}

void TranslucentMesh::markCommitted() { topologyChanged_ = transformChanged_ = visibilityChanged_ = false; }

std::size_t TranslucentMesh::memoryBytes() const {
    std::size_t bytes = engine_ ? engine_->memoryBytes() : 0;
    if (irradiance_) bytes += irradiance_->memoryBytes();
    if (vertexIrradiance_ && output_.reference) bytes += vertexIrradiance_->capacity() * sizeof(float);  // else the engine's
    return bytes;
}

}  // namespace opal
