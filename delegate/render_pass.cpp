#include "delegate/render_pass.h"

#include "delegate/camera.h"
#include "delegate/image/camera_view.h"
#include "delegate/render_delegate.h"
#include "delegate/image/renderer.h"
#include "schema/error.h"

#include <algorithm>
#include <chrono>

namespace opal {

namespace {

float** targetOf(AovTargets& targets, const hd::Token& aov) {
    if (aov == hd::Aov::Color) return &targets.color;
    if (aov == hd::Aov::Subsurface) return &targets.subsurface;
    if (aov == hd::Aov::Specular) return &targets.specular;
    if (aov == hd::Aov::Irradiance) return &targets.irradiance;
    if (aov == hd::Aov::Normal) return &targets.normal;
    if (aov == hd::Aov::Depth) return &targets.depth;
    if (aov == hd::Aov::PrimId) return &targets.primId;
    if (aov == hd::Aov::Alpha) return &targets.alpha;
    return nullptr;
}

}  // namespace

void OpalRenderPass::execute(const hd::RenderPassState& state, const std::vector<hd::AovBinding>& aovs) {
    const auto* camera = dynamic_cast<const OpalCamera*>(index_.sprim(state.camera));
    if (!camera) throw Error("Opal render pass: '" + state.camera + "' is not a camera prim of the render index");
    const CameraView view(camera->desc(), state.width, state.height, state.camera);
    for (const hd::AovBinding& binding : aovs) {
        if (aovChannelCount(binding.aov) == 0) {
            std::string known;
            for (const hd::Token& aov : supportedAovs()) known += (known.empty() ? "" : ", ") + aov;
            throw Error("Opal render pass: unknown AOV '" + binding.aov + "' (Opal renders " + known + ")");
        }
        if (!binding.buffer) throw Error("Opal render pass: AOV '" + binding.aov + "' is bound to no buffer");
    }
    const std::shared_ptr<const Frame> frame = delegate_.frame(index_);

    // The first binding of each AOV is rendered into; later ones get a copy.
    AovTargets targets;
    std::vector<std::pair<hd::RenderBuffer*, hd::RenderBuffer*>> copies;  // (to, from)
    std::vector<std::pair<hd::Token, hd::RenderBuffer*>> first;
    for (const hd::AovBinding& binding : aovs) {
        // A buffer of the right size is reused as it is: the renderer writes every pixel.
        const int channels = aovChannelCount(binding.aov);
        hd::RenderBuffer& buffer = *binding.buffer;
        if (buffer.width() != state.width || buffer.height() != state.height || buffer.channels() != channels)
            buffer.allocate(state.width, state.height, channels);
        float** target = targetOf(targets, binding.aov);
        if (!*target) {
            *target = binding.buffer->data().data();
            first.emplace_back(binding.aov, binding.buffer);
        } else {
            const auto source = std::find_if(first.begin(), first.end(), [&](const auto& f) { return f.first == binding.aov; });
            if (source->second != binding.buffer) copies.emplace_back(binding.buffer, source->second);
        }
    }

    const auto start = std::chrono::steady_clock::now();
    const RenderSettings& settings = delegate_.settings();
    renderFrame(*frame, view, RenderOptions{settings.specular, settings.transparentBackground, settings.tileSize}, targets);
    for (auto& [to, from] : copies) std::copy(from->data().begin(), from->data().end(), to->data().begin());
    delegate_.recordRender(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
}

}  // namespace opal
