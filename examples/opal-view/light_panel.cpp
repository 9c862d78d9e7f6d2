#include "examples/opal-view/light_panel.h"

#include "examples/opal-view/core/color_temperature.h"
#include "examples/opal-view/core/edited_scene.h"
#include "schema/error.h"

#include <imgui.h>

#include <optional>
#include <utility>

namespace opal::view {
namespace {

const char* kindName(const scene::SceneLight& light) {
    switch (light.desc.kind) {
    case hd::LightKind::Sphere: return light.desc.shapingConeAngle ? "spot" : light.desc.treatAsPoint ? "point" : "sphere";
    case hd::LightKind::Distant: return "distant";
    case hd::LightKind::Dome: return "dome";
    case hd::LightKind::ShadowField: return "shadow field";
    }
    return "light";
}

void addButtons(ViewerModel& model) {
    ImGui::TextUnformatted("Add");
    for (const NewLightKind kind : {NewLightKind::Point, NewLightKind::Distant, NewLightKind::Dome}) {
        ImGui::SameLine();
        if (ImGui::SmallButton(newLightKindName(kind))) model.addLight(kind);
    }
}

// Each light with its enable box; a disabled light stays listed, unlit.
void lightList(ViewerModel& model) {
    std::optional<std::pair<hd::SdfPath, bool>> toggled;
    for (const auto& [path, light] : model.scene().lights) {
        bool enabled = model.lightEnabled(path);
        if (ImGui::Checkbox(("##on" + path).c_str(), &enabled)) toggled = {path, enabled};
        ImGui::SameLine();
        const std::string label = path + "  (" + kindName(light) + ")";
        if (ImGui::Selectable(label.c_str(), model.selectedLight == path)) model.selectedLight = path;
    }
    if (toggled) model.setLightEnabled(toggled->first, toggled->second);
}

// Rename and remove the selected light; what the model refuses is shown under them.
void lightNaming(ViewerModel& model, const hd::SdfPath& path, std::string& problem) {
    static constexpr std::size_t NameLength = 128;
    char name[NameLength] = {};
    const std::string leaf = path.substr(path.find_last_of('/') + 1);
    leaf.copy(name, NameLength - 1);
    try {
        if (ImGui::InputText("name", name, NameLength, ImGuiInputTextFlags_EnterReturnsTrue)) {
            model.renameLight(path, name);
            problem.clear();
        }
        if (ImGui::Button("Remove light")) model.removeLight(path);
    } catch (const Error& e) {
        problem = e.what();
    }
    if (!problem.empty()) ImGui::TextWrapped("%s", problem.c_str());
}

// UsdLux's colour temperature: a checkbox, and the kelvin on a logarithmic slider.
bool colorTemperature(hd::LightDesc& light) {
    bool on = light.enableColorTemperature, changed = false;
    float kelvin = float(light.colorTemperature);
    if (ImGui::Checkbox("colour temperature", &on)) {
        setColorTemperature(light, on ? light.colorTemperature : 0.0);
        changed = true;
    }
    if (!on) return changed;
    if (ImGui::SliderFloat("kelvin", &kelvin, float(kMinColorTemperature), float(kMaxColorTemperature), "%.0f K",
                           ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp)) {
        setColorTemperature(light, kelvin);
        changed = true;
    }
    return changed;
}

void lightParameters(ViewerModel& model, const hd::SdfPath& path) {
    hd::LightDesc light = model.light(path);
    bool changed = emissionSliders(light);
    float color[3] = {float(light.color[0]), float(light.color[1]), float(light.color[2])};
    if (ImGui::ColorEdit3("color", color, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR)) {
        light.color = Rgb{std::max(color[0], 0.0f), std::max(color[1], 0.0f), std::max(color[2], 0.0f)};
        changed = true;
    }
    changed |= colorTemperature(light);
    if (changed) model.setLight(path, light);
    if (light.kind != hd::LightKind::Sphere) return;
    const Imath::V3d p = lightPosition(light);
    ImGui::Text("position (%.4g, %.4g, %.4g)", p.x, p.y, p.z);
    ImGui::TextDisabled("drag with the left button in the viewport to move it");
}

}  // namespace

bool emissionSliders(hd::LightDesc& light, const char* id) {
    bool changed = false;
    float intensity = float(light.intensity), exposure = float(light.exposure);
    if (ImGui::SliderFloat((std::string("intensity") + id).c_str(), &intensity, 0.0f, 1e7f, "%.4g",
                           ImGuiSliderFlags_Logarithmic)) {
        light.intensity = std::max(intensity, 0.0f);
        changed = true;
    }
    if (ImGui::SliderFloat((std::string("exposure") + id).c_str(), &exposure, -10.0f, 10.0f, "%.2f stops")) {
        light.exposure = exposure;
        changed = true;
    }
    return changed;
}

void drawLightPanel(ViewerModel& model, std::string& problem) {
    if (!ImGui::CollapsingHeader("Lights", ImGuiTreeNodeFlags_DefaultOpen)) return;
    addButtons(model);
    if (model.scene().lights.empty()) {
        ImGui::TextDisabled("the scene has no lights");
        return;
    }
    lightList(model);
    if (!model.selectedLight) return;
    const hd::SdfPath selected = *model.selectedLight;
    lightParameters(model, selected);
    lightNaming(model, selected, problem);
}

}  // namespace opal::view
