#include "examples/opal-view/color_panel.h"

#include <imgui.h>

#include <vector>

namespace opal::view {
namespace {

// A combo over `items`; the chosen one, or "" when nothing was picked this frame.
std::string pick(const char* label, const std::string& current, const std::vector<std::string>& items) {
    std::string chosen;
    if (!ImGui::BeginCombo(label, current.c_str())) return chosen;
    for (const std::string& item : items)
        if (ImGui::Selectable(item.c_str(), item == current)) chosen = item;
    ImGui::EndCombo();
    return chosen;
}

}  // namespace

void drawColorPanel(DisplayPicture& picture, DisplaySettings& settings, const std::vector<std::string>& aovs) {
    if (!ImGui::CollapsingHeader("Color", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const ColorConfig& config = picture.config();
    if (const std::string display = pick("display", picture.display(), config.displays()); !display.empty()) {
        picture.setDisplayView(display, config.defaultView(display));
        ++settings.version;
    }
    if (const std::string view = pick("view", picture.view(), config.views(picture.display())); !view.empty()) {
        picture.setDisplayView(picture.display(), view);
        ++settings.version;
    }
    float exposure = float(settings.grade.exposure), gamma = float(settings.grade.gamma);
    if (ImGui::SliderFloat("exposure", &exposure, -10.0f, 10.0f, "%.2f stops")) {
        settings.grade.exposure = exposure;
        ++settings.version;
    }
    if (ImGui::SliderFloat("gamma", &gamma, 0.2f, 5.0f, "%.2f", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp)) {
        settings.grade.gamma = gamma;
        ++settings.version;
    }
    if (const std::string aov = pick("AOV", settings.aov, aovs); !aov.empty()) {
        settings.aov = aov;
        ++settings.version;
    }
}

}  // namespace opal::view
