#include "delegate/render_settings.h"

#include "schema/error.h"

#include <array>

namespace opal {

namespace {

const hd::Token Reference = "opal:reference";
const hd::Token Specular = "opal:specular";
const hd::Token TransparentBackground = "opal:transparentBackground";
const hd::Token OcioConfig = "opal:ocioConfig";
const hd::Token TileSize = "opal:tileSize";

const std::array<hd::Token, 5> Names = {Reference, Specular, TransparentBackground, OcioConfig, TileSize};

[[noreturn]] void unknown(const hd::Token& key) {
    std::string known;
    for (const hd::Token& name : Names) known += (known.empty() ? "" : ", ") + name;
    throw Error("Opal render delegate: unknown render setting '" + key + "' (known: " + known +
                "; read-only statistics start with opal:stats:)");
}

[[noreturn]] void wrongType(const hd::Token& key, const char* expected, const hd::Value& value) {
    throw Error("Opal render delegate: render setting '" + key + "' must be " + expected + ", not " +
                valueTypeName(value));
}

bool requireBool(const hd::Token& key, const hd::Value& value) {
    if (const bool* b = std::get_if<bool>(&value)) return *b;
    wrongType(key, "a bool", value);
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

std::span<const hd::Token> RenderSettings::names() { return Names; }

bool RenderSettings::set(const hd::Token& key, const hd::Value& value) {
    if (key == Reference) return assign(reference, requireBool(key, value));
    if (key == Specular) return assign(specular, requireBool(key, value));
    if (key == TransparentBackground) return assign(transparentBackground, requireBool(key, value));
    if (key == OcioConfig) {
        const std::string* s = std::get_if<std::string>(&value);
        if (!s) wrongType(key, "a string (a file path, or empty)", value);
        return assign(ocioConfig, *s);
    }
    if (key == TileSize) {
        const int* n = std::get_if<int>(&value);
        if (!n) wrongType(key, "an int", value);
        if (*n < 1 || *n > 4096)
            throw Error("Opal render delegate: render setting '" + key + "' must be in [1, 4096], not " +
                        std::to_string(*n));
        return assign(tileSize, *n);
    }
    unknown(key);
}

hd::Value RenderSettings::get(const hd::Token& key) const {
    if (key == Reference) return reference;
    if (key == Specular) return specular;
    if (key == TransparentBackground) return transparentBackground;
    if (key == OcioConfig) return ocioConfig;
    if (key == TileSize) return tileSize;
    unknown(key);
}

std::map<hd::Token, hd::Value> RenderSettings::all() const {
    std::map<hd::Token, hd::Value> settings;
    for (const hd::Token& key : Names) settings[key] = get(key);
    return settings;
}

}  // namespace opal
