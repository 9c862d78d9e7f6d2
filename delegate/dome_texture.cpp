#include "delegate/dome_texture.h"

#include "delegate/relight/light_emission.h"
#include "schema/error.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <string>
#include <vector>

namespace opal {

std::shared_ptr<const LatLongMap> readLatLongMap(const std::string& file, const OCIO::ConstProcessorRcPtr& toWorking) {
    const auto fail = [&](const std::string& what) { throw Error("dome texture '" + file + "': " + what); };
    auto input = OIIO::ImageInput::open(file);
    if (!input) fail(OIIO::geterror());
    const OIIO::ImageSpec& spec = input->spec();
    const int width = spec.width, height = spec.height, channels = spec.nchannels;
    if (width <= 0 || height <= 0 || channels <= 0) fail("the image has no pixels");
    std::vector<float> pixels(std::size_t(width) * height * channels);
    if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data())) fail(input->geterror());
    input->close();

    std::vector<float> rgb(std::size_t(width) * height * 3);
    for (std::size_t p = 0; p < std::size_t(width) * height; ++p)
        for (int c = 0; c < 3; ++c) {
            const float v = pixels[p * channels + std::size_t(channels >= 3 ? c : 0)];
            if (!(v >= 0.0f && v <= kMaxEmittedRadiance))
                fail("texel (" + std::to_string(p % std::size_t(width)) + ", " + std::to_string(p / std::size_t(width)) +
                     ") channel " + std::to_string(c) + " is " + std::to_string(v) +
                     ": a dome's radiance must be finite, non-negative and at most 1e20");
            rgb[3 * p + c] = v;
        }
    try {
        OCIO::PackedImageDesc image(rgb.data(), width, height, 3);
        toWorking->getDefaultCPUProcessor()->apply(image);
    } catch (const OCIO::Exception& e) {
        fail(std::string("color conversion: ") + e.what());
    }
    // A colour outside the working space's gamut converts to a negative component: clipped
    // to zero (the working space cannot emit it; delegate/COLOR.md).
    for (float& v : rgb) v = std::max(v, 0.0f);
    std::shared_ptr<const LatLongMap> map;
    try {
        map = std::make_shared<const LatLongMap>(width, height, std::move(rgb));
    } catch (const Error& e) {
        fail(e.what());
    }
    return map;
}

std::shared_ptr<const LatLongMap> DomeTextureCache::get(const std::string& file, const std::string& colorSpace) {
    if (file.empty()) return std::make_shared<const LatLongMap>(2, 1, std::vector<float>(6, 1.0f));
    const auto key = std::make_pair(file, colorSpace);
    if (auto it = maps_.find(key); it != maps_.end()) return it->second;
    OCIO::ConstProcessorRcPtr toWorking;
    try {
        toWorking = config().toWorking(colorSpace);
    } catch (const Error& e) {
        throw Error("dome texture '" + file + "': " + e.what());
    }
    auto map = readLatLongMap(file, toWorking);
    maps_.emplace(key, map);
    return map;
}

void DomeTextureCache::reset(std::string ocioConfig) {
    ocioConfig_ = std::move(ocioConfig);
    config_.reset();
    maps_.clear();
}

const ColorConfig& DomeTextureCache::config() {
    if (!config_) config_ = ocioConfig_.empty() ? ColorConfig::fromEnvironment() : ColorConfig::fromFile(ocioConfig_);
    return *config_;
}

}  // namespace opal
