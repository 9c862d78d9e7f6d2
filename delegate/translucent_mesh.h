// The translucent mesh Rprim (a Mesh with OpalSubsurfaceAPI; hdEmbree's mesh): it pulls its
// MeshDesc for the dirty bits it is given and owns what relights it, a MeshIrradiance (E_m
// per light at the samples) and a RelightEngine (products, material, radiance). The
// delegate's commitResources drives it, redoing only what changed
// (docs/ARCHITECTURE.md#relighting and #irradiance):
//
//   Topology (a new asset)  new engine and irradiance; every light evaluated
//   Transform               MeshIrradiance::setTransform (every light: samples moved)
//   another mesh's geometry updateShadows (analytic lights only: occluders moved)
//   a light's version       that light's E only (setLight / removeLight)
//   any E change            RelightEngine::setIrradiance (the sparse products)
//   material binding/values RelightEngine::setMaterial only: O(K N), no products
//   opal:reference          the exact gather instead of the engine (reference_gather.h), from
//                           the true E (domes: environment_reference.h)
//
// An invisible mesh computes nothing and is relit in full when shown again.
#pragma once

#include "delegate/relight/commit_stats.h"
#include "delegate/hd/prim.h"
#include "delegate/relight/mesh_irradiance.h"
#include "delegate/relight/relight_engine.h"
#include "delegate/image/renderer.h"

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace opal {

// One light as a mesh's irradiance takes it (from an OpalLight), with its version.
struct LightSource {
    std::uint64_t version = 0;
    const AnalyticLight* analytic = nullptr;             // sphere and distant lights
    std::shared_ptr<const EnvironmentLight> environment;  // domes
    std::shared_ptr<const ShadowFieldLight> field;        // shadow-field lights
    bool shadowed() const { return analytic || field; }   // its E depends on occluders
};
using LightSources = std::map<hd::SdfPath, LightSource>;

// The material a mesh is bound to, resolved by the delegate: a material prim's values and
// version, or the asset's default material (empty path, version 0).
struct BoundMaterial {
    hd::SdfPath path;
    std::uint64_t version = 0;
    Material subsurface;
    bool specular = true;
    double roughness = hd::kDefaultSpecularRoughness;
};

class TranslucentMesh final : public hd::Rprim {
public:
    using hd::Rprim::Rprim;

    // Topology, Transform, Material (the binding) and Visibility pull the MeshDesc and take
    // the fields they name. Throws opal::Error naming the prim for a missing asset, an asset
    // the renderer cannot shade (vertex weights or normals that do not match the render
    // mesh) or an unsupported transform; the mesh keeps its previous state then.
    void sync(const hd::SceneDelegate& scene, hd::DirtyBits* dirtyBits) override;
    hd::DirtyBits initialDirtyBits() const override {
        return hd::Dirty::Topology | hd::Dirty::Transform | hd::Dirty::Material | hd::Dirty::Visibility;
    }

    const hd::MeshDesc& desc() const { return desc_; }
    bool visible() const { return desc_.visible && desc_.asset != nullptr; }
    // Whether topology, transform or visibility changed since the last commit: the ray
    // scene must be rebuilt.
    bool geometryChanged() const { return topologyChanged_ || transformChanged_ || visibilityChanged_; }

    // The delegate's commit, in this order, for a visible mesh. Errors name the mesh (and
    // the light or material involved).
    void updateIrradiance(const LightSources& lights, const RayScene& rays, bool raysRebuilt, CommitStats& stats);
    void updateMaterial(const BoundMaterial& material, CommitStats& stats, std::vector<std::string>& warnings);
    void updateRadiance(bool reference, int primId, CommitStats& stats);
    // For an invisible mesh instead: nothing is computed, and it is relit in full when shown.
    void hide();
    // Clears the changes of the last sync (after a successful commit).
    void markCommitted();

    // Bytes held by the mesh's relighting (engine and irradiance), 0 when hidden.
    std::size_t memoryBytes() const;

    // What the renderer shades; null until the mesh was relit once.
    std::shared_ptr<const MeshShading> shading() const { return shading_; }

private:
    void addLight(const hd::SdfPath& light, const LightSource& source, const RayScene& rays, CommitStats& stats);
    [[noreturn]] void fail(const std::string& what) const;

    hd::MeshDesc desc_;
    bool topologyChanged_ = false, transformChanged_ = false, visibilityChanged_ = false;

    std::unique_ptr<MeshIrradiance> irradiance_;
    std::unique_ptr<RelightEngine> engine_;
    std::map<hd::SdfPath, std::uint64_t> appliedLights_;  // light -> version in irradiance_
    bool relightInFull_ = true;

    BoundMaterial material_;            // as last applied to engine_
    bool engineHasMaterial_ = false;

    // Versions of what the outputs were formed from.
    std::uint64_t momentsVersion_ = 0, engineMoments_ = 0, materialVersion_ = 0;
    struct OutputKey {
        bool reference = false;
        std::uint64_t moments = 0, material = 0;
        int primId = -1;
        bool operator==(const OutputKey&) const = default;
    };
    OutputKey output_;
    std::shared_ptr<const MeshShading> shading_;
    // E per vertex: the engine's (held, recycled_buffer.h) or the reference's.
    std::shared_ptr<const std::vector<float>> vertexIrradiance_;
};

}  // namespace opal
