#include "examples/opal-view/light_panel.h"

#include "examples/opal-view/core/edited_scene.h"

#include <imgui.h>

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

void lightList(ViewerModel& model) {
    for (const auto& [path, light] : model.scene().lights) {
        const std::string label = path + "  (" + kindName(light) + ")";
        if (ImGui::Selectable(label.c_str(), model.selectedLight == path)) model.selectedLight = path;
    }
}

void lightParameters(ViewerModel& model, const hd::SdfPath& path) {
    hd::LightDesc light = model.light(path);
    bool changed = false;
    float intensity = float(light.intensity), exposure = float(light.exposure);
    float color[3] = {float(light.color[0]), float(light.color[1]), float(light.color[2])};
    if (ImGui::SliderFloat("intensity", &intensity, 0.0f, 1e7f, "%.4g", ImGuiSliderFlags_Logarithmic)) {
        light.intensity = std::max(intensity, 0.0f);
        changed = true;
    }
    if (ImGui::SliderFloat("exposure", &exposure, -10.0f, 10.0f, "%.2f stops")) {
        light.exposure = exposure;
        changed = true;
    }
    if (ImGui::ColorEdit3("color", color, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR)) {
        light.color = Rgb{std::max(color[0], 0.0f), std::max(color[1], 0.0f), std::max(color[2], 0.0f)};
        changed = true;
    }
    if (changed) model.setLight(path, light);
    if (light.kind != hd::LightKind::Sphere) return;
    const Imath::V3d p = lightPosition(light);
    ImGui::Text("position (%.4g, %.4g, %.4g)", p.x, p.y, p.z);
    ImGui::TextDisabled("drag with the left button in the viewport to move it");
}

}  // namespace

void drawLightPanel(ViewerModel& model) {
    if (!ImGui::CollapsingHeader("Lights", ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (model.scene().lights.empty()) {
        ImGui::TextDisabled("the scene has no lights");
        return;
    }
    lightList(model);
    if (model.selectedLight) lightParameters(model, *model.selectedLight);
}

}  // namespace opal::view
