// The preview delegate's render settings:
//
//   opal:preview:shading    string, "lambert" (default) or "normals"
//   opal:preview:headlight  0 to 100, the headlight's intensity (default 1: a head-on
//                           surface shows its albedo)
//
// A setting meant for another delegate (any other name: a scene authored for Opal sets
// opal:samplesPerPixel) is kept, reported once as ignored, and returned by value() and
// all(), as Hydra delegates keep settings they do not use; so a scene made for Opal opens
// in the preview. An unknown opal:preview:* name, or a value of the wrong type or range,
// throws opal::Error naming the setting.
#pragma once

#include "delegate/hd/render_setting_descriptor.h"
#include "delegate/preview/preview_shading.h"

#include <map>
#include <string>
#include <vector>

namespace opal::preview {

class PreviewSettings {
public:
    static std::vector<hd::RenderSettingDescriptor> descriptors();

    // Throws opal::Error for a bad own setting (the old value stays).
    void set(const hd::Token& key, const hd::Value& value);
    // Throws opal::Error for a name never set that is not the preview's.
    hd::Value value(const hd::Token& key) const;
    std::map<hd::Token, hd::Value> all() const;
    // "render setting 'K' is not the preview's: ignored", once per name, since the last call.
    std::vector<std::string> takeWarnings();

    Shading shading() const { return shading_; }
    double headlight() const { return headlight_; }

private:
    Shading shading_ = Shading::Lambert;
    double headlight_ = 1.0;
    std::map<hd::Token, hd::Value> ignored_;
    std::vector<std::string> warnings_;
};

}  // namespace opal::preview
