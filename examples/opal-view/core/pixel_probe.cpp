#include "examples/opal-view/core/pixel_probe.h"

#include "delegate/hd/aov.h"
#include "schema/error.h"

#include <cmath>
#include <cstdint>
#include <cstdio>

namespace opal::view {
namespace {

std::string values(const std::vector<float>& v) {
    std::string text;
    for (const float f : v) {
        char number[32];
        std::snprintf(number, sizeof number, "%.9g", double(f));
        if (!text.empty()) text += ' ';
        text += number;
    }
    return text;
}

std::string joined(const std::vector<std::string>& words) {
    std::string text;
    for (const std::string& w : words) {
        if (!text.empty()) text += ' ';
        text += w;
    }
    return text;
}

}  // namespace

std::vector<ProbedAov> probeAovs(const render::AovBuffers& buffers, int x, int y) {
    std::vector<ProbedAov> probed;
    for (const hd::AovBinding& binding : buffers.bindings()) {
        const hd::RenderBuffer& buffer = *binding.buffer;
        const hd::RenderBuffer::Mapped mapped(buffer);
        if (x < 0 || y < 0 || x >= buffer.width() || y >= buffer.height())
            throw Error("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                        std::to_string(buffer.width()) + "x" + std::to_string(buffer.height()) + " picture");
        ProbedAov aov{binding.aov, {}, {}};
        const hd::AovDescriptor* row = hd::findAov(binding.aov);
        const float* pixel = mapped.pixel(x, y);
        for (int c = 0; c < buffer.channels(); ++c) {
            aov.channels.push_back(row && c < row->channelCount() ? std::string(row->channels[c]) : std::to_string(c));
            aov.values.push_back(pixel[c]);
        }
        probed.push_back(std::move(aov));
    }
    return probed;
}

std::string probeReport(const PixelProbe& probe) {
    std::string text = "probe " + std::to_string(probe.x) + " " + std::to_string(probe.y) + "\n";
    for (const ProbedAov& aov : probe.aovs)
        text += "  " + aov.aov + " " + joined(aov.channels) + " = " + values(aov.values) + "\n";
    if (probe.display)
        text += "  display (" + probe.shownAov + ") R G B = " +
                values({(*probe.display)[0], (*probe.display)[1], (*probe.display)[2]}) + "\n";
    return text;
}

std::optional<std::array<float, 3>> shownValue(const Image& shown, int x, int y, int width, int height) {
    if (shown.empty() || width <= 0 || height <= 0 || x < 0 || y < 0) return std::nullopt;
    const int px = int(std::int64_t(x) * shown.width() / width), py = int(std::int64_t(y) * shown.height() / height);
    if (px >= shown.width() || py >= shown.height()) return std::nullopt;
    return std::array<float, 3>{shown.at(px, py, 0), shown.at(px, py, 1), shown.at(px, py, 2)};
}

std::optional<hd::SdfPath> primOfId(const scene::Scene& scene, const std::set<hd::SdfPath>& disabled, float id) {
    if (!(id >= 0.0f) || id != std::floor(id)) return std::nullopt;
    std::size_t n = std::size_t(id);
    if (n < scene.meshes.size()) return std::next(scene.meshes.begin(), std::ptrdiff_t(n))->first;
    n -= scene.meshes.size();
    for (const auto& [path, light] : scene.lights)
        if (light.desc.kind == hd::LightKind::ShadowField && !disabled.count(path) && n-- == 0) return path;
    return std::nullopt;
}

}  // namespace opal::view
