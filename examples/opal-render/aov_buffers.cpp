#include "examples/opal-render/aov_buffers.h"

#include "schema/error.h"

#include <algorithm>

namespace opal::render {
namespace {

const std::string ColorAov = "color";

bool contains(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

AovBuffers::AovBuffers(const std::vector<std::string>& requested, bool needColor) {
    std::vector<std::string> names = requested;
    if (names.empty())
        for (const hd::AovDescriptor& aov : hd::aovTable()) names.push_back(aov.name);
    for (const std::string& name : names) {
        if (contains(written_, name)) continue;
        if (name == "alpha" && contains(names, ColorAov)) continue;  // color's A
        written_.push_back(name);
    }
    for (const std::string& name : written_)
        bound_.push_back({name, std::make_unique<hd::RenderBuffer>("/OpalRender/Aovs/" + name)});
    if (needColor && !contains(written_, ColorAov))
        bound_.push_back({ColorAov, std::make_unique<hd::RenderBuffer>("/OpalRender/Aovs/" + ColorAov)});
}

std::vector<hd::AovBinding> AovBuffers::bindings() const {
    std::vector<hd::AovBinding> bindings;
    for (const Bound& bound : bound_) bindings.push_back({bound.aov, bound.buffer.get()});
    return bindings;
}

const AovBuffers::Bound& AovBuffers::find(const std::string& aov) const {
    const auto it = std::find_if(bound_.begin(), bound_.end(), [&](const Bound& b) { return b.aov == aov; });
    if (it == bound_.end()) throw Error("opal-render: AOV '" + aov + "' was not rendered");
    return *it;
}

Image AovBuffers::image(const Bound& bound) const {
    const hd::RenderBuffer& buffer = *bound.buffer;
    if (buffer.width() <= 0 || buffer.height() <= 0)
        throw Error("opal-render: the render delegate left AOV '" + bound.aov + "' unallocated");
    return Image(buffer.width(), buffer.height(), buffer.channels(), buffer.data());
}

std::vector<AovLayer> AovBuffers::exrLayers() const {
    std::vector<AovLayer> layers;
    for (const std::string& aov : written_) layers.push_back(makeAovLayer(aov, image(find(aov))));
    return layers;
}

Image AovBuffers::color() const { return image(find(ColorAov)); }

}  // namespace opal::render
