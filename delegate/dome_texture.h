// Dome light textures (docs/ARCHITECTURE.md#dome-light): a lat-long image read with OpenImageIO and
// converted to the working color space with the delegate's OCIO config (ColorConfig::toWorking of
// the light's textureColorSpace), cached by (file, color space) so that editing a dome's intensity
// or rotation never re-reads its file. A dome without a file is a constant white map, which the
// light's color and intensity scale (UsdLux).
#pragma once

#include "delegate/output/color_config.h"
#include "delegate/relight/environment_light.h"

#include <map>
#include <memory>
#include <optional>
#include <string>

namespace opal {

// Reads `file` (RGB or RGBA; one channel is grey) as float RGB and converts it with
// `toWorking`. Throws opal::Error naming the file (OpenImageIO's message) or a bad image.
std::shared_ptr<const LatLongMap> readLatLongMap(const std::string& file, const OCIO::ConstProcessorRcPtr& toWorking);

class DomeTextureCache {
public:
    // `ocioConfig` empty: $OCIO or the config Opal ships (ColorConfig::fromEnvironment).
    explicit DomeTextureCache(std::string ocioConfig = {}) : ocioConfig_(std::move(ocioConfig)) {}

    // The map of `file` in the working space; a constant white map for an empty file.
    // Throws opal::Error (file, color space, OCIO config).
    std::shared_ptr<const LatLongMap> get(const std::string& file, const std::string& colorSpace);

    // Forgets every map and the OCIO config (e.g. after opal:ocioConfig changed).
    void reset(std::string ocioConfig);
    std::size_t size() const { return maps_.size(); }

private:
    const ColorConfig& config();

    std::string ocioConfig_;
    std::optional<ColorConfig> config_;
    std::map<std::pair<std::string, std::string>, std::shared_ptr<const LatLongMap>> maps_;
};

}  // namespace opal
