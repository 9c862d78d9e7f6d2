// The light panel: add a point, sphere, spot, distant or dome light, or a shadow-field light
// from a baked light layer (its path typed in, ImGui having no file browser); every light of the scene
// with a box that enables it; the selected one's intensity, exposure and colour, its type's
// own parameters (radius, cone and softness, angle), (for a point, sphere or spot light) its
// position, which a left-button drag in the viewport changes, its name and removal.
#pragma once

#include "examples/opal-view/core/viewer_model.h"

#include <array>
#include <string>

namespace opal::view {

struct LightPanelState {
    std::string problem;  // the last refused addition, rename or removal, shown until one succeeds
    std::array<char, 1024> lightLayer{};  // the baked light layer's path being typed
};

void drawLightPanel(ViewerModel& model, LightPanelState& state);

// A light's intensity (logarithmic) and exposure sliders; `id` keeps two sets of them in
// one window apart ("##dome"). True when either changed.
bool emissionSliders(hd::LightDesc& light, const char* id = "");

}  // namespace opal::view
