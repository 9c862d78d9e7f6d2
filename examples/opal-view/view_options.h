// What one opal-view run is asked to do: the command line, parsed (main.cpp).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace opal::view {

struct ViewOptions {
    std::optional<std::filesystem::path> scene;       // SCENE.usda or ASSET.usda; none: the candle
    std::optional<std::filesystem::path> screenshot;  // --screenshot OUT.png, then exit
    std::optional<std::filesystem::path> script;      // --script FILE
    int width = 1280, height = 720;                   // --size WxH, the window
    std::optional<std::string> delegate;              // --delegate TYPE
};

}  // namespace opal::view
