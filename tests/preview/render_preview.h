// Renders a SphereScene on a delegate to convergence into the named AOVs, as a host does:
// a render index, a pass, buffers bound by name.
#pragma once

#include "delegate/hd/render_to_convergence.h"
#include "tests/preview/sphere_scene.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace opal::test {

struct Frame {
    std::map<std::string, std::unique_ptr<hd::RenderBuffer>> aovs;
    const float* at(const std::string& aov, int x, int y) const { return aovs.at(aov)->pixel(x, y); }
};

inline Frame renderSphere(hd::RenderDelegate& delegate, const SphereScene& scene,
                          const std::vector<std::string>& aovs = {"color"}) {
    Frame frame;
    std::vector<hd::AovBinding> bindings;
    for (const std::string& aov : aovs) {
        frame.aovs[aov] = std::make_unique<hd::RenderBuffer>("/Buffers/" + aov);
        bindings.push_back({aov, frame.aovs[aov].get()});
    }
    hd::RenderIndex index(delegate);
    scene.populate(index);
    index.sync();
    const std::unique_ptr<hd::RenderPass> pass = delegate.createRenderPass(index);
    hd::renderToConvergence(delegate, *pass, {CameraPath, Width, Height}, bindings);
    return frame;
}

}  // namespace opal::test
