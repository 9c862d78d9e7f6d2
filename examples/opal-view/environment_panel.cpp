#include "examples/opal-view/environment_panel.h"

#include "examples/opal-view/core/environment_edit.h"
#include "examples/opal-view/light_panel.h"
#include "schema/error.h"

#include <imgui.h>

#include <algorithm>
#include <array>

namespace opal::view {
namespace {

// The path field and its Load button; a refused file leaves the dome as it was.
bool textureField(hd::LightDesc& dome, EnvironmentPanelState& state) {
    std::array<char, 1024> text{};
    std::copy_n(state.texture.begin(), std::min(state.texture.size(), text.size() - 1), text.begin());
    const bool entered = ImGui::InputText("image", text.data(), text.size(), ImGuiInputTextFlags_EnterReturnsTrue);
    state.texture = text.data();
    if (!entered && !ImGui::Button("Load image")) return false;
    try {
        setEnvironmentTexture(dome, state.texture);
        state.problem.clear();
        return true;
    } catch (const Error& e) {
        state.problem = e.what();
        return false;
    }
}

}  // namespace

void drawEnvironmentPanel(ViewerModel& model, EnvironmentPanelState& state) {
    if (!ImGui::CollapsingHeader("Environment")) return;
    const std::optional<hd::SdfPath> path = environmentLight(model.scene());
    if (!path) {
        ImGui::TextDisabled("the scene has no dome light");
        if (ImGui::Button("Add dome")) model.addLight(NewLightKind::Dome);
        return;
    }
    hd::LightDesc dome = model.light(*path);
    ImGui::TextWrapped("%s", dome.textureFile.empty() ? "uniform (no image)" : dome.textureFile.c_str());
    bool changed = textureField(dome, state);
    float turn = float(environmentRotation(dome));
    if (ImGui::SliderFloat("rotation", &turn, -180.0f, 180.0f, "%.1f deg")) {
        rotateEnvironment(dome, turn - environmentRotation(dome));
        changed = true;
    }
    changed |= emissionSliders(dome, "##dome");
    changed |= ImGui::Checkbox("show as background", &dome.visibleToCamera);
    if (changed) model.setLight(*path, dome);
    if (!state.problem.empty()) ImGui::TextWrapped("%s", state.problem.c_str());
}

}  // namespace opal::view
