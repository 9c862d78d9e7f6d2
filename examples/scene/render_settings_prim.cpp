#include "examples/scene/render_settings_prim.h"

#include "examples/scene/scene_path.h"
#include "examples/scene/xformable.h"
#include "schema/error.h"

#include <charconv>

namespace opal::scene {
namespace {

using namespace usda::types;

bool validSide(long long side) { return side >= 1 && side <= Resolution::Max; }

std::string allowedSides() { return "each side in [1, " + std::to_string(Resolution::Max) + "]"; }

std::optional<Resolution> readResolution(PrimReader& reader) {
    const usda::Attribute* attribute = reader.find("resolution", {Int2});
    if (!attribute) return std::nullopt;
    const usda::Vec2i& r = std::get<usda::Vec2i>(attribute->value->data());
    if (!validSide(r[0]) || !validSide(r[1]))
        reader.failAt(*attribute, "is (" + std::to_string(r[0]) + ", " + std::to_string(r[1]) + "), expected " +
                                      allowedSides());
    return Resolution{r[0], r[1]};
}

// What an opal:* attribute hands the delegate.
hd::Value settingValue(PrimReader& reader, const usda::Attribute& attribute, const std::filesystem::path& layerFile) {
    const usda::ValueType type = attribute.type;
    if (type == Bool || type == Int || type == Float || type == Double || type == String || type == Token || type == Asset) {
        if (!reader.find(attribute.name, {type})) return std::monostate{};
        if (type == Asset) return reader.existingFile(attribute.name, layerFile)->string();
        return std::visit(
            [](const auto& v) -> hd::Value {
                using T = std::decay_t<decltype(v)>;
                if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, std::string>) return v;
                else if constexpr (std::is_same_v<T, std::int32_t>) return int(v);
                else if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) return double(v);
                else return std::monostate{};
            },
            attribute.value->data());
    }
    reader.failAt(attribute, "has type " + usda::typeName(type) +
                                 "; render settings are bool, int, float, double, string, token or asset");
}

std::vector<DelegateSetting> readDelegateSettings(PrimReader& reader, const std::filesystem::path& layerFile) {
    std::vector<DelegateSetting> settings;
    for (const usda::Property* property : reader.withPrefix("opal:")) {
        const auto* attribute = std::get_if<usda::Attribute>(property);
        if (!attribute) reader.fail(usda::propertyLocation(*property), "render settings are attributes, not relationships");
        hd::Value value = settingValue(reader, *attribute, layerFile);
        if (!std::holds_alternative<std::monostate>(value))
            settings.push_back({attribute->name, std::move(value), attribute->location});
    }
    return settings;
}

void readCamera(PrimReader& reader, SceneRenderSettings& settings) {
    const usda::Relationship* camera = reader.relationship("camera");
    if (!camera || !camera->targets) return;
    if (camera->targets->size() != 1)
        reader.failAt(*camera, "has " + std::to_string(camera->targets->size()) + " targets, expected one Camera");
    try {
        settings.camera = resolveTargetPath(reader.path(), camera->targets->front());
    } catch (const Error& e) {
        reader.failAt(*camera, e.what());
    }
    settings.cameraWhere = camera->location;
}

}  // namespace

Resolution parseResolution(std::string_view text) {
    const std::size_t x = text.find('x');
    long long width = 0, height = 0;
    const auto parse = [](std::string_view s, long long& v) {
        const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), v);
        return error == std::errc() && end == s.data() + s.size() && !s.empty();
    };
    if (x == std::string_view::npos || !parse(text.substr(0, x), width) || !parse(text.substr(x + 1), height))
        throw Error("resolution '" + std::string(text) + "': expected WIDTHxHEIGHT, e.g. 1920x1080");
    if (!validSide(width) || !validSide(height))
        throw Error("resolution '" + std::string(text) + "': expected " + allowedSides());
    return {int(width), int(height)};
}

SceneRenderSettings readRenderSettings(PrimReader& reader, const std::filesystem::path& layerFile) {
    rejectTransform(reader);
    SceneRenderSettings settings;
    settings.path = reader.path();
    settings.where = reader.prim().location;
    settings.resolution = readResolution(reader);
    readCamera(reader, settings);
    settings.delegateSettings = readDelegateSettings(reader, layerFile);
    reader.requireFallback<Float>("pixelAspectRatio", 1.0f, "pixels are square");
    reader.requireFallback<Token>("aspectRatioConformPolicy", "expandAperture",
                                  "the camera's aperture is always fitted into the image");
    reader.requireFallback<Float4>("dataWindowNDC", usda::Vec4f{0.0f, 0.0f, 1.0f, 1.0f}, "crop windows are not implemented");
    return settings;
}

void applyRenderSettings(const SceneRenderSettings& settings, hd::RenderDelegate& delegate) {
    for (const DelegateSetting& setting : settings.delegateSettings) {
        try {
            delegate.setRenderSetting(setting.name, setting.value);
        } catch (const Error& e) {
            throw usda::UsdaError(setting.where, "RenderSettings <" + settings.path + ">: attribute " +
                                                     quotedName(setting.name) + ": " + e.what());
        }
    }
}

}  // namespace opal::scene
