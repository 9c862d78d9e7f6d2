// Opal's render delegate (Hydra's HdRenderDelegate; hdEmbree's renderDelegate): creates
// Opal's prims by type, holds the render settings, and in commitResources brings the
// relighting state up to date after each sync, recomputing only what the dirty prims
// changed (translucent_mesh.h lists what each change costs). Its render thread draws the
// Frame of the last commit progressively into the bound buffers. Settings, AOVs, stats and
// conventions: delegate/DELEGATE.md.
//
// Threads: sync (and so commitResources), execute and destroying prims happen on one host
// thread; relighting runs there, inside commitResources, so a host whose interface must not
// wait for it calls sync from a worker thread (its buffers keep the previous frame's last
// pass meanwhile: the render thread stops, so that the relighting has every core). The render thread only reads immutable Frames. Buffers may be mapped,
// renderStats() read and pause/resume/stop called from any thread. One delegate serves one
// render index at a time (as in Hydra); the index and its render passes go before the
// delegate.
#pragma once

#include "delegate/relight/commit_stats.h"
#include "delegate/dome_texture.h"
#include "delegate/hd/render_delegate.h"
#include "delegate/prim_version.h"
#include "delegate/shadow_field_cache.h"
#include "delegate/render_job.h"
#include "delegate/render_settings.h"
#include "delegate/render_thread.h"

#include <atomic>
#include <chrono>
#include <mutex>
#include <optional>

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
    // A buffer the render thread fills is released by it first.
    void destroyPrim(std::unique_ptr<hd::Prim> prim) override;
    // Stops rendering and lets go of the index's frame and meshes.
    void finalizeRenderIndex(hd::RenderIndex& index) override;

    // hd/aov.h's table.
    std::vector<hd::AovDescriptor> aovDescriptors() const override;

    // RenderSettings (render_settings.h).
    void setRenderSetting(const hd::Token& key, const hd::Value& value) override;
    hd::Value renderSetting(const hd::Token& key) const override;
    std::map<hd::Token, hd::Value> renderSettings() const override;
    std::vector<hd::RenderSettingDescriptor> renderSettingDescriptors() const override;
    // delegate/DELEGATE.md lists them: progress, the last commit's split, memory per mesh.
    std::map<hd::Token, hd::Value> renderStats() const override;

    bool pause() override;
    bool resume() override;
    bool stop() override;

    std::unique_ptr<hd::RenderPass> createRenderPass(hd::RenderIndex& index) override;
    // Throws opal::Error naming the prim (and light or material) that failed; what failed
    // is retried by the next commit.
    void commitResources(hd::RenderIndex& index) override;

    // ---- Opal's own, for hosts linking the delegate, benchmarks and tests.
    const RenderSettings& settings() const { return settings_; }
    // The last commit's timings and counts, and the counts summed over every commit.
    // From the thread that syncs (renderStats() has them for any thread).
    const CommitStats& lastCommit() const { return lastCommit_; }
    const CommitStats& totals() const { return totals_; }
    std::uint64_t commits() const { return commits_; }
    // Warnings since the last call (materials clamped into an asset's editable range).
    std::vector<std::string> takeWarnings() override;
    std::vector<std::string> takeErrors() override;
    // Every translucent mesh of the last commit in primId order (by path; invisible ones
    // keep their number).
    const std::vector<hd::SdfPath>& meshPaths() const { return meshPaths_; }

    // For OpalRenderPass: renders the job (its frame and options filled in here from the
    // last commit and the settings), restarting the render thread unless it renders the same
    // picture already. Commits first if a setting that changes the frame (opal:reference,
    // opal:ocioConfig) changed. Throws opal::Error for an invalid camera or size.
    void render(hd::RenderIndex& index, RenderJob job);
    bool isConverged() const { return converged_.load(); }
    // Passes completed of the current job (0 .. passCount, + 1 with a draft), and their count.
    int passesDone() const { return passesDone_.load(); }

private:
    void reloadDomeTextures(hd::RenderIndex& index);  // after opal:ocioConfig changed
    void renderJob();  // the render thread's callback
    void commit(hd::RenderIndex& index);  // commitResources, with the render thread stopped
    void restart(RenderJob job);
    void publish(std::shared_ptr<const Frame> frame);
    void newJob();  // under jobMutex_: progress starts again
    std::shared_ptr<const Frame> frame(hd::RenderIndex& index);

    RenderSettings settings_;
    std::uint64_t settingsVersion_ = 0, committedSettingsVersion_ = 0;
    PrimVersions versions_;
    DomeTextureCache textures_;
    ShadowFieldCache fields_;
    std::string texturesConfig_;

    const hd::RenderIndex* index_ = nullptr;
    std::vector<const hd::Rprim*> committedMeshes_;
    std::vector<hd::SdfPath> meshPaths_;
    std::shared_ptr<const Frame> frame_;

    // The commit's figures, written by commitResources and read by renderStats() from any thread.
    mutable std::mutex statsMutex_;
    CommitStats lastCommit_, totals_;
    std::uint64_t commits_ = 0;
    std::vector<std::pair<hd::SdfPath, std::size_t>> meshMemory_;  // engine bytes per mesh, last commit
    std::vector<std::string> warnings_;

    // The render thread's job and progress (job_ under jobMutex_).
    mutable std::mutex jobMutex_;
    std::optional<RenderJob> job_;
    std::vector<std::string> renderErrors_;
    std::chrono::steady_clock::time_point jobStart_;
    std::uint64_t jobGeneration_ = 0;  // one per job (a restart is a new job)
    std::atomic<int> passesDone_{0}, passCount_{0}, draftPasses_{0};  // passes of the current job (the draft counts)
    std::atomic<double> lastPassMs_{0.0}, convergedMs_{0.0};
    std::atomic<bool> converged_{false};
    RenderThread thread_{[this] { renderJob(); }};  // last: stops before the members it uses go
};

}  // namespace opal
