// The render settings of Opal's delegate: one table of descriptors (name, type, default,
// range, help; hd::RenderSettingDescriptor) that validation, renderSettings(), hosts'
// settings panels and delegate/DELEGATE.md derive from.
#pragma once

#include "delegate/hd/render_setting_descriptor.h"
#include "delegate/image/pixel_filter.h"

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
    int samplesPerPixel = 16;            // opal:samplesPerPixel: sub-pixel samples a converged pixel holds
    PixelFilter pixelFilter = PixelFilter::Box;  // opal:pixelFilter
    int draftBlock = 1;                  // opal:draftBlock: a restarted frame's draft, one ray per N x N pixels

    // Every writable setting, in the order DELEGATE.md gives them.
    static std::span<const hd::RenderSettingDescriptor> descriptors();

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
