#include "delegate/render_settings.h"

#include "schema/error.h"

#include <algorithm>
#include <array>

namespace opal {

namespace {

const hd::Token Reference = "opal:reference";
const hd::Token Specular = "opal:specular";
const hd::Token TransparentBackground = "opal:transparentBackground";
const hd::Token OcioConfig = "opal:ocioConfig";
const hd::Token TileSize = "opal:tileSize";
const hd::Token SamplesPerPixel = "opal:samplesPerPixel";
const hd::Token PixelFilterKey = "opal:pixelFilter";
const hd::Token DraftBlock = "opal:draftBlock";

std::vector<std::string> filterChoices() {
    std::vector<std::string> choices;
    for (std::string_view name : pixelFilterNames()) choices.emplace_back(name);
    return choices;
}

const std::array<hd::RenderSettingDescriptor, 8>& table() {
    static const std::array<hd::RenderSettingDescriptor, 8> rows = {{
        {Reference, "Reference", false, {}, {}, {},
         "render with the exact dipole gather (O(N^2) per mesh) instead of the relighting engine"},
        {Specular, "Specular", true, {}, {}, {}, "the GGX specular layer (a material can also turn its own off)"},
        {TransparentBackground, "Transparent background", false, {}, {}, {},
         "where no object is hit: colour 0 and alpha 0 instead of the visible domes"},
        {OcioConfig, "OCIO config", std::string(), {}, {}, {},
         "the OCIO config dome textures are converted with; empty: $OCIO, else Opal's own"},
        {TileSize, "Tile size", 32, 1.0, 4096.0, {}, "pixels per side of one render task"},
        {SamplesPerPixel, "Samples per pixel", 16, 1.0, 1024.0, {},
         "sub-pixel samples a converged pixel averages (1: the ray through the centre only)"},
        {PixelFilterKey, "Pixel filter", std::string("box"), {}, {}, filterChoices(),
         "how a pixel's samples are weighted: box or blackmanHarris"},
        {DraftBlock, "Draft block", 1, 1.0, 16.0, {},
         "a (re)started frame first shows a draft with one ray per N x N pixels; 1: no draft"},
    }};
    return rows;
}

[[noreturn]] void unknown(const hd::Token& key) {
    std::string known;
    for (const hd::RenderSettingDescriptor& d : table()) known += (known.empty() ? "" : ", ") + d.key;
    throw Error("Opal render delegate: unknown render setting '" + key + "' (known: " + known + ")");
}

[[noreturn]] void wrongType(const hd::Token& key, const hd::Value& expected, const hd::Value& value) {
    throw Error("Opal render delegate: render setting '" + key + "' must be a" +
                (expected.index() == 1 ? " bool" : expected.index() == 2 ? "n int" : " string") + ", not " +
                valueTypeName(value));
}

// The value, checked against the descriptor's type, range and choices.
const hd::Value& checked(const hd::Token& key, const hd::Value& value) {
    const auto& rows = table();
    const auto row = std::find_if(rows.begin(), rows.end(), [&](const auto& d) { return d.key == key; });
    if (row == rows.end()) unknown(key);
    if (value.index() != row->defaultValue.index()) wrongType(key, row->defaultValue, value);
    if (const int* n = std::get_if<int>(&value); n && (*n < *row->min || *n > *row->max))
        throw Error("Opal render delegate: render setting '" + key + "' must be in [" +
                    std::to_string(int(*row->min)) + ", " + std::to_string(int(*row->max)) + "], not " +
                    std::to_string(*n));
    if (const std::string* s = std::get_if<std::string>(&value);
        s && !row->choices.empty() && std::find(row->choices.begin(), row->choices.end(), *s) == row->choices.end())
    {
        std::string choices;
        for (const std::string& c : row->choices) choices += (choices.empty() ? "" : ", ") + c;
        throw Error("Opal render delegate: render setting '" + key + "' is '" + *s + "', not one of " + choices);
    }
    return value;
}

template <typename T>
bool assign(T& field, const T& value) {
    if (field == value) return false;
    field = value;
    return true;
}

}  // namespace

std::string valueTypeName(const hd::Value& value) {
    switch (value.index()) {
        case 0: return "empty";
        case 1: return "bool";
        case 2: return "int";
        case 3: return "double";
        default: return "string";
    }
}

std::span<const hd::RenderSettingDescriptor> RenderSettings::descriptors() { return table(); }

bool RenderSettings::set(const hd::Token& key, const hd::Value& value) {
    const hd::Value& v = checked(key, value);
    if (key == Reference) return assign(reference, std::get<bool>(v));
    if (key == Specular) return assign(specular, std::get<bool>(v));
    if (key == TransparentBackground) return assign(transparentBackground, std::get<bool>(v));
    if (key == OcioConfig) return assign(ocioConfig, std::get<std::string>(v));
    if (key == TileSize) return assign(tileSize, std::get<int>(v));
    if (key == SamplesPerPixel) return assign(samplesPerPixel, std::get<int>(v));
    if (key == DraftBlock) return assign(draftBlock, std::get<int>(v));
    return assign(pixelFilter, parsePixelFilter(std::get<std::string>(v)));
}

hd::Value RenderSettings::get(const hd::Token& key) const {
    if (key == Reference) return reference;
    if (key == Specular) return specular;
    if (key == TransparentBackground) return transparentBackground;
    if (key == OcioConfig) return ocioConfig;
    if (key == TileSize) return tileSize;
    if (key == SamplesPerPixel) return samplesPerPixel;
    if (key == PixelFilterKey) return std::string(pixelFilterName(pixelFilter));
    if (key == DraftBlock) return draftBlock;
    unknown(key);
}

std::map<hd::Token, hd::Value> RenderSettings::all() const {
    std::map<hd::Token, hd::Value> settings;
    for (const hd::RenderSettingDescriptor& d : table()) settings[d.key] = get(d.key);
    return settings;
}

}  // namespace opal
