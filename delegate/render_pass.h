// Opal's render pass (hdEmbree's renderPass): execute() validates the bindings, allocates
// each buffer to the pass's size with its AOV's channels (hd/aov.h) and hands the frame to
// the delegate's render thread, which fills the buffers progressively (image/renderer.h)
// while execute returns. Called again with nothing changed, it lets the frame go on.
#pragma once

#include "delegate/hd/render_index.h"
#include "delegate/hd/render_pass.h"

namespace opal {

class OpalRenderDelegate;

class OpalRenderPass final : public hd::RenderPass {
public:
    OpalRenderPass(OpalRenderDelegate& delegate, hd::RenderIndex& index) : delegate_(delegate), index_(index) {}
    // Stops the render thread: what this pass started renders no more.
    ~OpalRenderPass() override;

    // Throws opal::Error for a camera path that is not a camera prim of the index, a
    // non-positive size, an unknown AOV (listing Opal's), an AOV bound twice or a binding
    // without a buffer; nothing is rendered then.
    void execute(const hd::RenderPassState& state, const std::vector<hd::AovBinding>& aovs) override;
    bool isConverged() const override;

private:
    OpalRenderDelegate& delegate_;
    hd::RenderIndex& index_;
};

}  // namespace opal
