#include "examples/opal-view/core/display_picture.h"

#include "delegate/hd/aov.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace opal::view {
namespace {

// Every pixel's first three channels (or its one channel, repeated) through `f`.
template <class F>
Image perPixel(const Image& in, F&& f) {
    Image out(in.width(), in.height(), 3);
    for (int y = 0; y < in.height(); ++y)
        for (int x = 0; x < in.width(); ++x) {
            float rgb[3];
            for (int c = 0; c < 3; ++c) rgb[c] = in.at(x, y, std::min(c, in.channels() - 1));
            f(rgb);
            for (int c = 0; c < 3; ++c) out.at(x, y, c) = rgb[c];
        }
    return out;
}

Image normals(const Image& in) {
    return perPixel(in, [](float* n) {
        for (int c = 0; c < 3; ++c) n[c] = 0.5f * n[c] + 0.5f;
    });
}

Image depth(const Image& in) {
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (const float d : in.pixels())
        if (std::isfinite(d)) lo = std::min(lo, d), hi = std::max(hi, d);
    const float span = hi > lo ? hi - lo : 1.0f;
    return perPixel(in, [&](float* d) {
        const float v = std::isfinite(d[0]) ? 1.0f - 0.8f * (d[0] - lo) / span : 0.0f;
        std::fill(d, d + 3, v);
    });
}

Image ids(const Image& in) {
    float top = 0.0f;
    for (const float id : in.pixels()) top = std::max(top, id);
    return perPixel(in, [&](float* id) { std::fill(id, id + 3, id[0] < 0.0f ? 0.0f : (id[0] + 1.0f) / (top + 1.0f)); });
}

}  // namespace

bool isRadiometric(const std::string& aov) {
    const hd::AovDescriptor* row = hd::findAov(aov);
    return row && row->sampling == hd::AovSampling::Filtered && row->channelCount() >= 3;
}

Image mappedImage(const hd::RenderBuffer& buffer) {
    const hd::RenderBuffer::Mapped mapped(buffer);
    if (buffer.width() <= 0 || buffer.height() <= 0) return {};
    return Image(buffer.width(), buffer.height(), buffer.channels(), mapped.data());
}

DisplayPicture::DisplayPicture(const ColorConfig& config) : config_(config), transform_(config_) {}

void DisplayPicture::setDisplayView(const std::string& display, const std::string& view) {
    transform_ = DisplayTransform(config_, display, view);
}

// Display-referred RGB (the first three channels) to the power 1 / gamma.
void applyGamma(Image& image, double gamma) {
    if (gamma == 1.0) return;
    const float power = float(1.0 / gamma);
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            for (int c = 0; c < 3; ++c) image.at(x, y, c) = std::pow(std::max(image.at(x, y, c), 0.0f), power);
}

Image DisplayPicture::toDisplay(const Image& sceneLinear, const std::string& aov, const DisplayGrade& grade) const {
    if (sceneLinear.empty()) return {};
    if (aov == "normal") return normals(sceneLinear);
    if (aov == "depth") return depth(sceneLinear);
    if (aov == "primId") return ids(sceneLinear);
    if (!isRadiometric(aov)) return perPixel(sceneLinear, [](float*) {});
    const float gain = float(std::exp2(grade.exposure));
    Image rgb = perPixel(sceneLinear, [gain](float* c) {
        for (int i = 0; i < 3; ++i) c[i] *= gain;
    });
    transform_.applyInPlace(rgb);
    applyGamma(rgb, grade.gamma);
    return rgb;
}

Image DisplayPicture::toFile(const Image& sceneLinear, const std::string& aov, const DisplayGrade& grade) const {
    if (aov != "color" || sceneLinear.channels() != 4) return toDisplay(sceneLinear, aov, grade);
    Image rgba = sceneLinear;
    const float gain = float(std::exp2(grade.exposure));
    for (int y = 0; y < rgba.height(); ++y)
        for (int x = 0; x < rgba.width(); ++x)
            for (int c = 0; c < 3; ++c) rgba.at(x, y, c) *= gain;
    transform_.applyInPlace(rgba);
    applyGamma(rgba, grade.gamma);
    return rgba;
}

}  // namespace opal::view
