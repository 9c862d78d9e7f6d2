// Opal's render pass (hdEmbree's renderPass): renders the delegate's last committed frame
// through a camera prim into the bound AOV buffers, allocating each to the pass's size with
// the AOV's channels unless it has them already (delegate/DELEGATE.md).
#pragma once

#include "delegate/hd/render_index.h"
#include "delegate/hd/render_pass.h"

namespace opal {

class OpalRenderDelegate;

class OpalRenderPass final : public hd::RenderPass {
public:
    OpalRenderPass(OpalRenderDelegate& delegate, hd::RenderIndex& index) : delegate_(delegate), index_(index) {}

    // Throws opal::Error for a camera path that is not a camera prim of the index, a
    // non-positive size, an unknown AOV (listing Opal's) or a binding without a buffer;
    // nothing is written then.
    void execute(const hd::RenderPassState& state, const std::vector<hd::AovBinding>& aovs) override;

private:
    OpalRenderDelegate& delegate_;
    hd::RenderIndex& index_;
};

}  // namespace opal
