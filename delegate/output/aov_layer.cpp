#include "delegate/output/aov_layer.h"

#include "schema/error.h"

#include <array>
#include <utility>

namespace opal {
namespace {

struct AovConvention {
    std::string_view name;
    std::string_view exrLayer;
    std::vector<std::string> channels;  // the full set; color may drop its trailing A
    AovStorage storage;
};

const std::vector<AovConvention>& conventions() {
    static const std::vector<AovConvention> table = {
        {"color", "", {"R", "G", "B", "A"}, AovStorage::Color},
        {"subsurface", "subsurface", {"R", "G", "B"}, AovStorage::Color},
        {"specular", "specular", {"R", "G", "B"}, AovStorage::Color},
        {"irradiance", "irradiance", {"R", "G", "B"}, AovStorage::Color},
        {"normal", "normal", {"X", "Y", "Z"}, AovStorage::Color},
        {"depth", "depth", {"Z"}, AovStorage::Exact},
        {"primId", "primId", {"id"}, AovStorage::Exact},
        {"alpha", "", {"A"}, AovStorage::Color},
    };
    return table;
}

const AovConvention& findConvention(std::string_view name) {
    for (const AovConvention& c : conventions()) {
        if (c.name == name) return c;
    }
    std::string known;
    for (std::string_view n : standardAovNames())
        known += (known.empty() ? "" : ", ") + std::string(n);
    throw Error("AOV '" + std::string(name) + "': not one of Opal's AOVs (" + known + ")");
}

// color may come without alpha (alpha then travels as its own AOV).
bool acceptsChannelCount(const AovConvention& c, int count) {
    const int full = static_cast<int>(c.channels.size());
    return count == full || (c.name == "color" && count == 3);
}

}  // namespace

std::string AovLayer::exrChannelName(std::size_t channel) const {
    const std::string& suffix = channels.at(channel);
    return exrLayer.empty() ? suffix : exrLayer + "." + suffix;
}

std::span<const std::string_view> standardAovNames() {
    static constexpr std::array<std::string_view, 8> names = {
        "color", "subsurface", "specular", "irradiance", "normal", "depth", "primId", "alpha"};
    return names;
}

AovLayer makeAovLayer(std::string_view name, Image image) {
    const AovConvention& c = findConvention(name);
    if (!acceptsChannelCount(c, image.channels())) {
        throw Error("AOV '" + std::string(name) + "': image has " +
                    std::to_string(image.channels()) + " channels, expected " +
                    std::to_string(c.channels.size()) + (c.name == "color" ? " or 3" : ""));
    }
    AovLayer layer;
    layer.name = std::string(c.name);
    layer.exrLayer = std::string(c.exrLayer);
    layer.channels.assign(c.channels.begin(), c.channels.begin() + image.channels());
    layer.storage = c.storage;
    layer.image = std::move(image);
    return layer;
}

}  // namespace opal
