// A batch host's render (usdrecord's loop): execute the pass, then wait until its buffers
// are final. For hosts that want a finished image rather than a progressive one.
#pragma once

#include "delegate/hd/render_delegate.h"

namespace opal::hd {

// Throws opal::Error with what the delegate's render thread reported failing (takeErrors).
void renderToConvergence(RenderDelegate& delegate, RenderPass& pass, const RenderPassState& state,
                         const std::vector<AovBinding>& aovs);

}  // namespace opal::hd
