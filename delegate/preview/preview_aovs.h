// The AOVs the preview renders, described as Opal describes them (hd/aov.h) except that
// every one is the single sample through the pixel centre (Nearest): the preview does not
// anti-alias. Subsurface, specular, emission and irradiance are Opal's light transport:
// the preview has none and does not claim them.
#pragma once

#include "delegate/hd/aov.h"

#include <vector>

namespace opal::preview {

std::vector<hd::AovDescriptor> previewAovs();
// Throws opal::Error for an AOV the preview does not render, listing those it does.
const hd::AovDescriptor& requirePreviewAov(const std::vector<hd::AovDescriptor>& aovs, const hd::Token& name);

}  // namespace opal::preview
