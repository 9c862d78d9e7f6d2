// What a renderer implements (Hydra's HdRenderDelegate): it creates and destroys prims
// by type, holds render settings, creates render passes, and commits resources after a
// sync. Hosts obtain one from a RendererPlugin found by plugin/'s registry.
#pragma once

#include "delegate/hd/aov.h"
#include "delegate/hd/prim.h"
#include "delegate/hd/render_pass.h"
#include "delegate/hd/render_setting_descriptor.h"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace opal::hd {

class RenderIndex;

class RenderDelegate {
public:
    virtual ~RenderDelegate() = default;

    virtual std::vector<Token> supportedRprimTypes() const = 0;
    virtual std::vector<Token> supportedSprimTypes() const = 0;
    virtual std::vector<Token> supportedBprimTypes() const = 0;

    // nullptr for an unsupported type.
    virtual std::unique_ptr<Rprim> createRprim(const Token& type, const SdfPath& id) = 0;
    virtual std::unique_ptr<Sprim> createSprim(const Token& type, const SdfPath& id) = 0;
    virtual std::unique_ptr<Bprim> createBprim(const Token& type, const SdfPath& id) = 0;
    // The render index gives every prim back here to be destroyed (Hydra's DestroyRprim...):
    // the delegate lets go of what it holds for the prim first. The default just deletes it.
    virtual void destroyPrim(std::unique_ptr<Prim> prim) { prim.reset(); }
    // The render index is going away (after destroying its prims through destroyPrim): the
    // delegate stops rendering it and frees what it built from it.
    virtual void finalizeRenderIndex(RenderIndex&) {}

    // The AOVs the delegate renders, and how each is described (hd/aov.h). The default
    // descriptor of an unknown name is null.
    virtual std::vector<AovDescriptor> aovDescriptors() const = 0;
    std::optional<AovDescriptor> defaultAovDescriptor(const Token& name) const {
        for (AovDescriptor& row : aovDescriptors())
            if (row.name == name) return std::move(row);
        return std::nullopt;
    }

    // Settings are named "opal:..." (documented by each delegate); unknown names throw.
    virtual void setRenderSetting(const Token& key, const Value& value) = 0;
    virtual Value renderSetting(const Token& key) const = 0;
    virtual std::map<Token, Value> renderSettings() const = 0;
    virtual std::vector<RenderSettingDescriptor> renderSettingDescriptors() const = 0;
    // What the delegate is doing and holds (Hydra's GetRenderStats), by name; documented by
    // each delegate.
    virtual std::map<Token, Value> renderStats() const = 0;

    // Hydra's render thread controls: pause keeps the frame and uses no CPU until resume;
    // stop ends the frame (the next execute starts it again). Each returns whether the
    // delegate supports it.
    virtual bool pause() { return false; }
    virtual bool resume() { return false; }
    virtual bool stop() { return false; }

    virtual std::unique_ptr<RenderPass> createRenderPass(RenderIndex& index) = 0;
    // Called once after every sync of the index: the delegate updates what depends on
    // several prims (lights -> irradiance -> relighting).
    virtual void commitResources(RenderIndex& index) = 0;

    // What the delegate noticed but rendered anyway since the last call (e.g. a material
    // clamped into an asset's editable range), one message each, for the host to report.
    // Hydra routes these through TfDiagnostic, a process-wide sink; here the host pulls.
    virtual std::vector<std::string> takeWarnings() { return {}; }
    // What failed on the render thread since the last call (the frame was left as it was).
    virtual std::vector<std::string> takeErrors() { return {}; }
};

}  // namespace opal::hd
