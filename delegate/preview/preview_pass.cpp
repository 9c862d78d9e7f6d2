#include "delegate/preview/preview_pass.h"

#include "delegate/preview/preview_aovs.h"
#include "delegate/preview/preview_frame.h"
#include "delegate/preview/preview_prims.h"
#include "schema/error.h"

#include <chrono>
#include <cstring>

namespace opal::preview {
namespace {

// Where a pixel keeps the channels of `aov` (one of previewAovs()).
const float* channelsOf(const PreviewPixel& pixel, hd::AovId aov) {
    switch (aov) {
    case hd::AovId::Color: return pixel.color;
    case hd::AovId::Normal: return pixel.normal;
    case hd::AovId::Depth: return &pixel.depth;
    case hd::AovId::PrimId: return &pixel.primId;
    default: return &pixel.color[3];  // alpha
    }
}

// The whole frame at once; the buffer is only reallocated (cleared) when its size changes,
// so a reader sees the last frame until this one is written.
void writeAov(hd::RenderBuffer& buffer, const hd::AovDescriptor& aov, const std::vector<PreviewPixel>& pixels, int width,
              int height) {
    const int channels = aov.channelCount();
    if (buffer.width() != width || buffer.height() != height || buffer.channels() != channels)
        buffer.allocate(width, height, channels, aov.clearValue);
    const hd::AovId id = hd::aovId(aov.name);
    buffer.writeTiles([&](float* data) {
        for (std::size_t i = 0; i < pixels.size(); ++i)
            std::memcpy(data + i * channels, channelsOf(pixels[i], id), sizeof(float) * channels);
    });
    buffer.setConverged(true);
}

}  // namespace

void PreviewRenderPass::execute(const hd::RenderPassState& state, const std::vector<hd::AovBinding>& aovs) {
    converged_ = false;
    // Reported, not thrown: an exception made here must not outlive the module, which a
    // host may unload while unwinding (the host's renderToConvergence throws its own).
    try {
        render(state, aovs);
    } catch (const std::exception& e) {
        delegate_.reportError(e.what());
    }
    converged_ = true;  // a failed frame is final: the buffers keep what they held
}

void PreviewRenderPass::render(const hd::RenderPassState& state, const std::vector<hd::AovBinding>& aovs) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<hd::AovDescriptor> described = delegate_.aovDescriptors();
    for (const hd::AovBinding& binding : aovs) {
        requirePreviewAov(described, binding.aov);
        if (!binding.buffer) throw Error("preview delegate: AOV '" + binding.aov + "' has no buffer");
    }
    const auto* camera = dynamic_cast<const PreviewCamera*>(index_.sprim(state.camera));
    if (!camera) throw Error("preview delegate: no camera <" + state.camera + "> in the render index");
    const CameraView view(camera->desc(), state.width, state.height, state.camera);
    const PreviewScene* scene = delegate_.scene();
    if (!scene) throw Error("preview delegate: execute before the index's first commitResources");
    delegate_.framed(false, 0.0);
    const std::vector<PreviewPixel> pixels = renderFrame(*scene, view, delegate_.look());
    for (const hd::AovBinding& binding : aovs)
        writeAov(*binding.buffer, requirePreviewAov(described, binding.aov), pixels, state.width, state.height);
    delegate_.framed(true, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
}

}  // namespace opal::preview
