#include "delegate/preview/preview_aovs.h"

#include "schema/error.h"

namespace opal::preview {

std::vector<hd::AovDescriptor> previewAovs() {
    std::vector<hd::AovDescriptor> aovs;
    for (const hd::AovId id : {hd::AovId::Color, hd::AovId::Normal, hd::AovId::Depth, hd::AovId::PrimId, hd::AovId::Alpha}) {
        hd::AovDescriptor aov = hd::aovDescriptor(id);
        aov.sampling = hd::AovSampling::Nearest;
        if (id == hd::AovId::Color) aov.meaning = "scene-linear radiance, premultiplied by A: albedo x headlight x cos, or the normal";
        aovs.push_back(aov);
    }
    return aovs;
}

const hd::AovDescriptor& requirePreviewAov(const std::vector<hd::AovDescriptor>& aovs, const hd::Token& name) {
    std::string known;
    for (const hd::AovDescriptor& aov : aovs) {
        if (aov.name == name) return aov;
        known += (known.empty() ? "" : ", ") + aov.name;
    }
    throw Error("preview delegate: it does not render AOV '" + name + "' (it renders " + known + ")");
}

}  // namespace opal::preview
