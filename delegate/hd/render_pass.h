// Renders the current state of a render index through one camera into AOV buffers
// (Hydra's HdRenderPass + HdRenderPassState + HdRenderPassAovBinding).
#pragma once

#include "delegate/hd/render_buffer.h"

#include <vector>

namespace opal::hd {

struct AovBinding {
    Token aov;                      // an AOV name (hd/aov.h)
    RenderBuffer* buffer = nullptr; // allocated by the pass to the viewport size
};

struct RenderPassState {
    SdfPath camera;
    int width = 640, height = 480;
};

class RenderPass {
public:
    virtual ~RenderPass() = default;
    // Starts (or goes on) rendering the index's current state into the buffers and returns;
    // a render thread fills them (RenderBuffer::map reads them meanwhile). Called again with
    // nothing changed, it lets the running frame go on.
    virtual void execute(const RenderPassState& state, const std::vector<AovBinding>& aovs) = 0;
    // Whether every bound buffer holds its final values for the last execute.
    virtual bool isConverged() const = 0;
};

}  // namespace opal::hd
