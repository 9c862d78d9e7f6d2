// What one opal-render run is asked to do: the command line, parsed (main.cpp).
#pragma once

#include "examples/scene/render_settings_prim.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace opal::render {

struct RenderOptions {
    std::filesystem::path scene;                   // SCENE.usda
    std::filesystem::path output;                  // -o OUT.exr
    std::optional<std::filesystem::path> preview;  // --preview OUT.png
    std::optional<scene::Resolution> resolution;   // --resolution WxH
    std::vector<std::string> aovs;                 // --aov NAME ...; empty: every standard AOV
    std::optional<std::string> display, view;      // --display, --view (for the preview)
    std::optional<std::string> material;           // --material PRESET
    bool reference = false;                        // --reference: opal:reference on
    bool floatPixels = false;                      // --float: 32-bit color layers
    std::optional<std::string> camera;             // --camera /Path
    std::optional<std::string> delegate;           // --delegate TYPE: a renderer plugin type
    double time = 0.0;                             // --time SECONDS: the scene time (flicker)
    // --frames START:END [--step S]: time codes (the layer's timeCodesPerSecond), one
    // numbered EXR (and preview) per frame: OUT.0001.exr.
    struct Frames {
        int start = 0, end = 0, step = 1;
    };
    std::optional<Frames> frames;
};

}  // namespace opal::render
