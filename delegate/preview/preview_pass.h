// The preview's render pass: in execute, the whole frame through the camera prim
// (preview_frame.h) into the bound buffers; converged once execute returns. Buffers are
// written whole under writeTiles, so a host's map() never sees half a frame.
#pragma once

#include "delegate/hd/render_index.h"
#include "delegate/preview/preview_delegate.h"

#include <atomic>

namespace opal::preview {

class PreviewRenderPass final : public hd::RenderPass {
public:
    PreviewRenderPass(hd::RenderIndex& index, PreviewRenderDelegate& delegate) : index_(index), delegate_(delegate) {}

    // A camera the index lacks or rejects, an AOV the preview does not render or a buffer
    // missing is reported through the delegate's takeErrors; the buffers then keep what
    // they held and the pass counts as converged (the failed frame is final).
    void execute(const hd::RenderPassState& state, const std::vector<hd::AovBinding>& aovs) override;
    bool isConverged() const override { return converged_; }

private:
    void render(const hd::RenderPassState& state, const std::vector<hd::AovBinding>& aovs);

    hd::RenderIndex& index_;
    PreviewRenderDelegate& delegate_;
    std::atomic<bool> converged_{false};  // the host asks while execute runs
};

}  // namespace opal::preview
