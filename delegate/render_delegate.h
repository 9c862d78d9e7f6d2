// Opal's render delegate (Hydra's HdRenderDelegate; hdEmbree's renderDelegate): creates
// Opal's prims by type, holds the render settings, and in commitResources brings the
// relighting state up to date after each sync, recomputing only what the dirty prims
// changed (translucent_mesh.h lists what each change costs). Render passes draw the Frame
// of the last commit. Settings, AOVs and conventions: delegate/DELEGATE.md.
//
// One delegate serves one render index at a time (as in Hydra); the index and its render
// passes must be destroyed before the delegate. Not thread-safe: sync, commit and execute
// from one thread (each is parallel inside).
#pragma once

#include "delegate/relight/commit_stats.h"
#include "delegate/dome_texture.h"
#include "delegate/hd/render_delegate.h"
#include "delegate/prim_version.h"
#include "delegate/render_settings.h"
#include "delegate/image/renderer.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace opal {

class OpalRenderDelegate final : public hd::RenderDelegate {
public:
    // Throws opal::Error for an unknown or invalid setting.
    explicit OpalRenderDelegate(const std::map<hd::Token, hd::Value>& settings = {});
    ~OpalRenderDelegate() override;

    // translucentMesh; camera, material, sphereLight, distantLight, domeLight; renderBuffer.
    std::vector<hd::Token> supportedRprimTypes() const override;
    std::vector<hd::Token> supportedSprimTypes() const override;
    std::vector<hd::Token> supportedBprimTypes() const override;
    std::unique_ptr<hd::Rprim> createRprim(const hd::Token& type, const hd::SdfPath& id) override;
    std::unique_ptr<hd::Sprim> createSprim(const hd::Token& type, const hd::SdfPath& id) override;
    std::unique_ptr<hd::Bprim> createBprim(const hd::Token& type, const hd::SdfPath& id) override;

    // The writable settings (RenderSettings); "opal:stats:..." names are read-only: reading
    // them gives statisticNames()' values, writing them throws.
    void setRenderSetting(const hd::Token& key, const hd::Value& value) override;
    hd::Value renderSetting(const hd::Token& key) const override;
    // The writable settings only (what a host may pass back to createRenderDelegate).
    std::map<hd::Token, hd::Value> renderSettings() const override;

    std::unique_ptr<hd::RenderPass> createRenderPass(hd::RenderIndex& index) override;
    // Throws opal::Error naming the prim (and light or material) that failed; what failed
    // is retried by the next commit.
    void commitResources(hd::RenderIndex& index) override;

    // ---- Opal's own, for hosts linking the delegate, benchmarks and tests.
    const RenderSettings& settings() const { return settings_; }
    // The last commit's timings and counts, and the counts summed over every commit.
    const CommitStats& lastCommit() const { return lastCommit_; }
    const CommitStats& totals() const { return totals_; }
    std::uint64_t commits() const { return commits_; }
    double lastRenderMs() const { return lastRenderMs_; }
    static std::vector<hd::Token> statisticNames();
    // Warnings since the last call (materials clamped into an asset's editable range).
    std::vector<std::string> takeWarnings() override;
    // Every translucent mesh of the last commit in primId order (by path; invisible ones
    // keep their number).
    const std::vector<hd::SdfPath>& meshPaths() const { return meshPaths_; }

    // For OpalRenderPass: the committed frame (null before the first commit); commits
    // first if a setting that changes it (opal:reference, opal:ocioConfig) changed.
    std::shared_ptr<const Frame> frame(hd::RenderIndex& index);
    void recordRender(double ms) { lastRenderMs_ = ms; }

private:
    RenderSettings settings_;
    std::uint64_t settingsVersion_ = 0, committedSettingsVersion_ = 0;
    PrimVersions versions_;
    DomeTextureCache textures_;
    std::string texturesConfig_;

    const hd::RenderIndex* index_ = nullptr;
    std::vector<const hd::Rprim*> committedMeshes_;
    std::vector<hd::SdfPath> meshPaths_;
    std::shared_ptr<const Frame> frame_;

    CommitStats lastCommit_, totals_;
    std::uint64_t commits_ = 0;
    double lastRenderMs_ = 0.0;
    std::vector<std::string> warnings_;
};

}  // namespace opal
