#include "delegate/preview/preview_settings.h"

#include "schema/error.h"

#include <cmath>

namespace opal::preview {
namespace {

const hd::Token ShadingKey = "opal:preview:shading";
const hd::Token HeadlightKey = "opal:preview:headlight";
const std::string OwnPrefix = "opal:preview:";
constexpr double MaxHeadlight = 100.0;

const char* shadingName(Shading shading) { return shading == Shading::Lambert ? "lambert" : "normals"; }

Shading parseShading(const hd::Value& value) {
    const std::string* name = std::get_if<std::string>(&value);
    if (name && *name == "lambert") return Shading::Lambert;
    if (name && *name == "normals") return Shading::Normals;
    throw Error("preview delegate: render setting '" + ShadingKey + "' must be \"lambert\" or \"normals\"" +
                (name ? ", not \"" + *name + "\"" : std::string(", not a non-string value")));
}

double parseHeadlight(const hd::Value& value) {
    double number = NAN;
    if (const double* d = std::get_if<double>(&value)) number = *d;
    else if (const int* i = std::get_if<int>(&value)) number = *i;
    else throw Error("preview delegate: render setting '" + HeadlightKey + "' must be a number");
    if (!(number >= 0.0 && number <= MaxHeadlight))
        throw Error("preview delegate: render setting '" + HeadlightKey + "' must lie in [0, 100], not " +
                    std::to_string(number));
    return number;
}

}  // namespace

std::vector<hd::RenderSettingDescriptor> PreviewSettings::descriptors() {
    return {
        {ShadingKey, "Shading", hd::Value(std::string("lambert")), std::nullopt, std::nullopt, {"lambert", "normals"},
         "lambert: albedo x headlight x cos(view, normal); normals: the world normal as 0.5 (n + 1)"},
        {HeadlightKey, "Headlight", hd::Value(1.0), 0.0, MaxHeadlight, {},
         "the intensity of the light at the camera: a head-on surface shows albedo x this"},
    };
}

void PreviewSettings::set(const hd::Token& key, const hd::Value& value) {
    if (key == ShadingKey) {
        shading_ = parseShading(value);
    } else if (key == HeadlightKey) {
        headlight_ = parseHeadlight(value);
    } else if (key.starts_with(OwnPrefix)) {
        throw Error("preview delegate: unknown render setting '" + key + "' (it has " + ShadingKey + " and " +
                    HeadlightKey + ")");
    } else {
        if (!ignored_.count(key))
            warnings_.push_back("preview delegate: render setting '" + key + "' is not the preview's: ignored");
        ignored_[key] = value;
    }
}

hd::Value PreviewSettings::value(const hd::Token& key) const {
    if (key == ShadingKey) return std::string(shadingName(shading_));
    if (key == HeadlightKey) return headlight_;
    const auto it = ignored_.find(key);
    if (it == ignored_.end()) throw Error("preview delegate: unknown render setting '" + key + "'");
    return it->second;
}

std::map<hd::Token, hd::Value> PreviewSettings::all() const {
    std::map<hd::Token, hd::Value> settings = ignored_;
    settings[ShadingKey] = value(ShadingKey);
    settings[HeadlightKey] = value(HeadlightKey);
    return settings;
}

std::vector<std::string> PreviewSettings::takeWarnings() {
    std::vector<std::string> warnings;
    warnings.swap(warnings_);
    return warnings;
}

}  // namespace opal::preview
