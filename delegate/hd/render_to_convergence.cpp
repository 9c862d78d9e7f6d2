#include "delegate/hd/render_to_convergence.h"

#include "schema/error.h"

#include <chrono>
#include <thread>

namespace opal::hd {

void renderToConvergence(RenderDelegate& delegate, RenderPass& pass, const RenderPassState& state,
                         const std::vector<AovBinding>& aovs) {
    pass.execute(state, aovs);
    // Polling as Hydra hosts do; a millisecond is noise against a pass.
    while (!pass.isConverged()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    std::string errors;
    for (const std::string& e : delegate.takeErrors()) errors += (errors.empty() ? "" : "; ") + e;
    if (!errors.empty()) throw Error(errors);
}

}  // namespace opal::hd
