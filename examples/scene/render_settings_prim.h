// A scene's RenderSettings prim (UsdRenderSettings): the image resolution, the camera
// (rel camera) and the render delegate's settings, authored as opal:* attributes and
// handed to the delegate unchanged (bool -> bool, int -> int, float/double -> double,
// string/token -> string, asset -> the resolved file path as a string). The delegate
// decides which names and values it accepts (delegate/DELEGATE.md for Opal's).
#pragma once

#include "delegate/hd/render_delegate.h"
#include "examples/scene/prim_reader.h"

#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

namespace opal::scene {

struct Resolution {
    int width = 0, height = 0;

    static constexpr int Max = 16384;  // per side
    friend bool operator==(const Resolution&, const Resolution&) = default;
};

// "1920x1080" -> {1920, 1080}. Throws opal::Error for any other form or a side outside
// [1, Resolution::Max].
Resolution parseResolution(std::string_view text);

// A render setting as authored, with its place for messages.
struct DelegateSetting {
    hd::Token name;  // "opal:reference"
    hd::Value value;
    usda::SourceLocation where;
};

struct SceneRenderSettings {
    hd::SdfPath path;
    usda::SourceLocation where;
    std::optional<Resolution> resolution;
    std::optional<hd::SdfPath> camera;  // the target of rel camera, resolved
    usda::SourceLocation cameraWhere;
    std::vector<DelegateSetting> delegateSettings;  // in authored order
};

// Throws UsdaError at the attribute at fault: a resolution side outside
// [1, Resolution::Max], an opal:* attribute of another type, a camera relationship
// without exactly one prim target, a standard attribute away from its fallback.
SceneRenderSettings readRenderSettings(PrimReader& reader, const std::filesystem::path& layerFile);

// Sets each delegate setting on `delegate`; a setting the delegate refuses throws
// UsdaError at the attribute, carrying the delegate's message.
void applyRenderSettings(const SceneRenderSettings& settings, hd::RenderDelegate& delegate);

}  // namespace opal::scene
