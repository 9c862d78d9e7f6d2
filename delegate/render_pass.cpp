#include "delegate/render_pass.h"

#include "delegate/camera.h"
#include "delegate/image/camera_view.h"
#include "delegate/render_delegate.h"
#include "schema/error.h"

namespace opal {

namespace {

AovTargets targetsOf(const std::vector<hd::AovBinding>& aovs) {
    AovTargets targets{};
    for (const hd::AovBinding& binding : aovs) {
        const hd::AovId id = hd::aovId(binding.aov);  // throws for an unknown AOV, listing Opal's
        if (!binding.buffer) throw Error("Opal render pass: AOV '" + binding.aov + "' is bound to no buffer");
        if (targets[std::size_t(id)])
            throw Error("Opal render pass: AOV '" + binding.aov + "' is bound twice (bind it once and copy it)");
        targets[std::size_t(id)] = binding.buffer;
    }
    return targets;
}

}  // namespace

OpalRenderPass::~OpalRenderPass() { delegate_.stop(); }

void OpalRenderPass::execute(const hd::RenderPassState& state, const std::vector<hd::AovBinding>& aovs) {
    const auto* camera = dynamic_cast<const OpalCamera*>(index_.sprim(state.camera));
    if (!camera) throw Error("Opal render pass: '" + state.camera + "' is not a camera prim of the render index");
    AovTargets targets;
    try {
        targets = targetsOf(aovs);
    } catch (const Error& e) {
        throw Error(std::string(e.what()).starts_with("Opal render pass") ? e.what()
                                                                         : "Opal render pass: " + std::string(e.what()));
    }
    RenderJob job;
    job.camera = camera->desc();
    job.cameraPath = state.camera;
    job.width = state.width;
    job.height = state.height;
    job.targets = targets;
    delegate_.render(index_, std::move(job));
}

bool OpalRenderPass::isConverged() const { return delegate_.isConverged(); }

}  // namespace opal
