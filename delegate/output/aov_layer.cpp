#include "delegate/output/aov_layer.h"

#include "schema/error.h"

#include <utility>

namespace opal {

std::string AovLayer::exrChannelName(std::size_t channel) const {
    const std::string& suffix = channels.at(channel);
    return exrLayer.empty() ? suffix : exrLayer + "." + suffix;
}

AovLayer makeAovLayer(std::string_view name, Image image) {
    const hd::AovDescriptor* aov = hd::findAov(name);
    if (!aov) throw Error("AOV '" + std::string(name) + "': not one of Opal's AOVs (" + hd::aovNameList() + ")");
    const bool isColor = aov->name == "color";
    if (image.channels() != aov->channelCount() && !(isColor && image.channels() == 3))
        throw Error("AOV '" + std::string(name) + "': image has " + std::to_string(image.channels()) +
                    " channels, expected " + std::to_string(aov->channelCount()) + (isColor ? " or 3" : ""));
    AovLayer layer;
    layer.name = aov->name;
    layer.exrLayer = std::string(aov->exrLayer);
    layer.channels.assign(aov->channels.begin(), aov->channels.begin() + image.channels());
    layer.format = aov->format;
    layer.image = std::move(image);
    return layer;
}

}  // namespace opal
