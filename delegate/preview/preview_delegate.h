// OpalPreviewRenderDelegate: a quick look at a scene of translucent assets, with none of
// Opal's light transport. Each mesh is rendered opaque, with its material's total diffuse
// reflectance (the artist albedo, schema/scatter/material.h's toArtist) under a headlight
// (preview_shading.h); the scene's lights and domes are accepted and ignored. One ray per
// pixel centre through Embree, the whole frame in execute (tens of milliseconds for the
// viewer's window, in parallel with TBB), so it needs no render thread and has none to pause.
//
// Prims: translucentMesh; camera, material, and the four light types (kept, unused);
// renderBuffer. AOVs: color, normal, depth, primId, alpha (preview_aovs.h); the others
// are Opal's light transport and are refused. Settings: preview_settings.h. Stats:
// passes (1 once the frame is rendered), frameMs, meshes, triangles, lightsIgnored.
#pragma once

#include "delegate/hd/render_delegate.h"
#include "delegate/preview/preview_frame.h"
#include "delegate/preview/preview_scene.h"
#include "delegate/preview/preview_settings.h"

#include <memory>
#include <mutex>

namespace opal::preview {

class PreviewRenderDelegate final : public hd::RenderDelegate {
public:
    // Throws opal::Error for a bad setting (preview_settings.h).
    explicit PreviewRenderDelegate(const std::map<hd::Token, hd::Value>& settings = {});

    std::vector<hd::Token> supportedRprimTypes() const override;
    std::vector<hd::Token> supportedSprimTypes() const override;
    std::vector<hd::Token> supportedBprimTypes() const override;
    std::unique_ptr<hd::Rprim> createRprim(const hd::Token& type, const hd::SdfPath& id) override;
    std::unique_ptr<hd::Sprim> createSprim(const hd::Token& type, const hd::SdfPath& id) override;
    std::unique_ptr<hd::Bprim> createBprim(const hd::Token& type, const hd::SdfPath& id) override;
    void destroyPrim(std::unique_ptr<hd::Prim> prim) override;
    void finalizeRenderIndex(hd::RenderIndex& index) override;

    std::vector<hd::AovDescriptor> aovDescriptors() const override;

    void setRenderSetting(const hd::Token& key, const hd::Value& value) override;
    hd::Value renderSetting(const hd::Token& key) const override;
    std::map<hd::Token, hd::Value> renderSettings() const override;
    std::vector<hd::RenderSettingDescriptor> renderSettingDescriptors() const override;
    std::map<hd::Token, hd::Value> renderStats() const override;

    std::unique_ptr<hd::RenderPass> createRenderPass(hd::RenderIndex& index) override;
    // Rebuilds the Embree scene when a mesh synced or went, and the albedos every time. What
    // fails (a mesh Embree refuses, a bad material) goes to takeErrors; the last scene stays.
    void commitResources(hd::RenderIndex& index) override;
    std::vector<std::string> takeWarnings() override;
    std::vector<std::string> takeErrors() override;

    // For the render pass (on the thread that syncs): null before the first commit.
    const PreviewScene* scene() const { return scene_.get(); }
    FrameLook look() const;
    // The pass finished a frame (passes: 1) or started one (passes: 0).
    void framed(bool done, double milliseconds);
    // For takeErrors: what failed in the pass.
    void reportError(std::string message);

private:
    // The host reads settings and stats on its own thread while the pass renders: both
    // are kept under mutex_ (and the scene is replaced under it).
    mutable std::mutex mutex_;
    PreviewSettings settings_;
    std::unique_ptr<PreviewScene> scene_;
    int meshSyncs_ = 0, builtAt_ = -1;  // mesh syncs and removals; the count the scene was built at
    int lights_ = 0;
    int passes_ = 0;
    std::vector<std::string> errors_;
    double frameMs_ = 0.0;
};

}  // namespace opal::preview
