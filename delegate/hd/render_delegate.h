// What a renderer implements (Hydra's HdRenderDelegate): it creates and destroys prims
// by type, holds render settings, creates render passes, and commits resources after a
// sync. Hosts obtain one from a RendererPlugin found by plugin/'s registry.
#pragma once

#include "delegate/hd/prim.h"
#include "delegate/hd/render_pass.h"

#include <map>
#include <memory>
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

    // Settings are named "opal:..." (documented by each delegate); unknown names throw.
    virtual void setRenderSetting(const Token& key, const Value& value) = 0;
    virtual Value renderSetting(const Token& key) const = 0;
    virtual std::map<Token, Value> renderSettings() const = 0;

    virtual std::unique_ptr<RenderPass> createRenderPass(RenderIndex& index) = 0;
    // Called once after every sync of the index: the delegate updates what depends on
    // several prims (lights -> irradiance -> relighting).
    virtual void commitResources(RenderIndex& index) = 0;

    // What the delegate noticed but rendered anyway since the last call (e.g. a material
    // clamped into an asset's editable range), one message each, for the host to report.
    // Hydra routes these through TfDiagnostic, a process-wide sink; here the host pulls.
    virtual std::vector<std::string> takeWarnings() { return {}; }
};

}  // namespace opal::hd
