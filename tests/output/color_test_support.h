// Helpers shared by the color and image-output tests: paths to the configs, a temporary
// directory, reproducible random images.
#pragma once

#include "delegate/output/color_config.h"
#include "delegate/output/image.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace opal::test {

inline std::filesystem::path shippedConfig() {
    return std::filesystem::path(OPAL_SOURCE_DIR) / "delegate/output/ocio/config.ocio";
}

// The studio ACES CG config from ../shared/assets (absent in a user's clone).
inline std::filesystem::path studioConfig() {
    return std::filesystem::path(OPAL_SHARED_ASSETS) /
           "ocio/cg-config-v1.0.0_aces-v1.3_ocio-v2.1.ocio";
}

// A fresh directory under the system temp dir, removed with everything in it.
class TempDir {
public:
    TempDir() {
        std::string pattern =
            (std::filesystem::temp_directory_path() / "opal-color-XXXXXX").string();
        if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
        path_ = pattern;
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::permissions(path_, std::filesystem::perms::owner_all,
                                     std::filesystem::perm_options::add, ignored);
        std::filesystem::remove_all(path_, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::directory_iterator(path_)) {
            names.push_back(e.path().filename().string());
        }
        return names;
    }

private:
    std::filesystem::path path_;
};

// Scene-linear test content: colors log-uniform over [2^-8, 2^4] (shadows to highlights)
// with a few exact zeros, alpha (4th channel) uniform in [0, 1] or 1 when opaque.
inline Image randomSceneLinear(int width, int height, int channels, unsigned seed, bool opaque) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> stops(-8.0f, 4.0f);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    Image image(width, height, channels);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            for (int c = 0; c < channels; ++c) {
                const bool alpha = c == 3;
                float v = alpha ? (opaque ? 1.0f : unit(rng)) : std::exp2(stops(rng));
                if (!alpha && (x + y + c) % 29 == 0) v = 0.0f;
                image.at(x, y, c) = v;
            }
        }
    }
    return image;
}

// The same display/view built straight from the OCIO API on an independently loaded
// config, applied one pixel at a time.
inline Image referenceDisplay(const Image& sceneLinear, const std::string& display,
                              const std::string& view) {
    const OCIO::ConstConfigRcPtr config =
        OCIO::Config::CreateFromFile(test::shippedConfig().c_str());
    OCIO::DisplayViewTransformRcPtr transform = OCIO::DisplayViewTransform::Create();
    transform->setSrc(OCIO::ROLE_SCENE_LINEAR);
    transform->setDisplay(display.c_str());
    transform->setView(view.c_str());
    const OCIO::ConstCPUProcessorRcPtr cpu =
        config->getProcessor(transform)->getDefaultCPUProcessor();
    Image out = sceneLinear;
    for (int y = 0; y < out.height(); ++y) {
        for (int x = 0; x < out.width(); ++x) cpu->applyRGB(&out.at(x, y, 0));
    }
    return out;
}

}  // namespace opal::test
