// Renders the current state of a render index through one camera into AOV buffers
// (Hydra's HdRenderPass + HdRenderPassState + HdRenderPassAovBinding).
#pragma once

#include "delegate/hd/render_buffer.h"

#include <vector>

namespace opal::hd {

struct AovBinding {
    Token aov;                      // one of hd::Aov
    RenderBuffer* buffer = nullptr; // allocated by the pass to the viewport size
};

struct RenderPassState {
    SdfPath camera;
    int width = 640, height = 480;
};

class RenderPass {
public:
    virtual ~RenderPass() = default;
    virtual void execute(const RenderPassState& state, const std::vector<AovBinding>& aovs) = 0;
};

}  // namespace opal::hd
