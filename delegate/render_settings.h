// The render settings of Opal's delegate (delegate/DELEGATE.md lists them): what a host may
// set through hd::RenderDelegate::setRenderSetting, validated here. Read-only statistics
// ("opal:stats:...") are the delegate's own (render_delegate.h).
#pragma once

#include "delegate/hd/types.h"

#include <map>
#include <span>
#include <string>

namespace opal {

struct RenderSettings {
    bool reference = false;              // opal:reference: exact dipole gather instead of the relighting engine
    bool specular = true;                // opal:specular: the GGX layer (each material may turn it off too)
    bool transparentBackground = false;  // opal:transparentBackground: alpha 0 and no dome behind the objects
    std::string ocioConfig;              // opal:ocioConfig: the OCIO config for dome textures; "" = $OCIO or Opal's
    int tileSize = 32;                   // opal:tileSize: pixels per side of a render task

    // Every writable setting's name, in the order DELEGATE.md gives them.
    static std::span<const hd::Token> names();

    // Throws opal::Error naming the setting for an unknown name (listing the known ones), a
    // value of the wrong type (no conversions: a bool setting takes a bool) or out of range.
    // Returns whether the value changed.
    bool set(const hd::Token& key, const hd::Value& value);
    // Throws opal::Error for an unknown name.
    hd::Value get(const hd::Token& key) const;
    std::map<hd::Token, hd::Value> all() const;
};

// "bool", "int", "double", "string" or "empty": for error messages.
std::string valueTypeName(const hd::Value& value);

}  // namespace opal
