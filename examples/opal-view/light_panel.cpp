#include "examples/opal-view/light_panel.h"

#include "examples/opal-view/core/color_temperature.h"
#include "examples/opal-view/core/edited_scene.h"
#include "examples/opal-view/core/light_flicker_edit.h"
#include "examples/opal-view/core/light_shape.h"
#include "examples/opal-view/core/prim_path.h"
#include "examples/scene/scene_lights.h"
#include "schema/error.h"

#include <imgui.h>

#include <algorithm>
#include <limits>
#include <optional>
#include <utility>

namespace opal::view {
namespace {

constexpr double kDefaultCone = 30.0;  // degrees, when the box makes a sphere light a spot

const char* kindName(const scene::SceneLight& light) {
    switch (light.desc.kind) {
    case hd::LightKind::Sphere: return light.desc.shapingConeAngle ? "spot" : light.desc.treatAsPoint ? "point" : "sphere";
    case hd::LightKind::Distant: return "distant";
    case hd::LightKind::Dome: return "dome";
    case hd::LightKind::ShadowField: return "shadow field";
    }
    return "light";
}

void addButtons(ViewerModel& model, LightPanelState& state) {
    ImGui::TextUnformatted("Add");
    const float indent = ImGui::GetCursorPosX() + ImGui::CalcTextSize("Add").x + ImGui::GetStyle().ItemSpacing.x;
    int n = 0;
    for (const NewLightKind kind : newLightKinds()) {
        if (n++ % 3 == 0 && n > 1) ImGui::SetCursorPosX(indent);  // three a row: the panel is narrow
        else ImGui::SameLine();
        if (ImGui::SmallButton(newLightKindName(kind))) model.addLight(kind);
    }
    const ImGuiStyle& style = ImGui::GetStyle();
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("shadow field").x -
                            2.0f * style.FramePadding.x - style.ItemSpacing.x);
    const bool entered = ImGui::InputTextWithHint("##lightLayer", "baked light layer (.usda)", state.lightLayer.data(),
                                                  state.lightLayer.size(), ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (!(ImGui::SmallButton("shadow field") || entered) || state.lightLayer[0] == '\0') return;
    try {
        model.addShadowFieldLight(std::filesystem::path(state.lightLayer.data()));
        state.problem.clear();
    } catch (const Error& e) {
        state.problem = e.what();
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
    const std::string leaf = primName(path);
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

// The type's own parameters (light_shape.h): a sphere's radius, a spot's cone and softness
// (a box makes a sphere light a spot), a distant light's angular diameter.
bool shapeSliders(hd::LightDesc& light) {
    bool changed = false;
    float value = 0.0f;
    if (hasShapeParameter(light, "radius")) {
        value = float(light.radius);
        const float step = std::max(0.01f * value, 1e-4f);
        if (ImGui::DragFloat("radius", &value, step, 0.0f, std::numeric_limits<float>::max(), "%.4g",
                             ImGuiSliderFlags_AlwaysClamp)) {
            light.radius = value;
            changed = true;
        }
    }
    if (hasShapeParameter(light, "cone")) {
        bool spot = light.shapingConeAngle.has_value();
        if (ImGui::Checkbox("spot cone", &spot)) {
            light.shapingConeAngle = spot ? std::optional<double>(kDefaultCone) : std::nullopt;
            changed = true;
        }
    }
    if (light.shapingConeAngle) {
        value = float(*light.shapingConeAngle);
        if (ImGui::SliderFloat("cone", &value, 0.0f, float(scene::MaxConeAngle), "%.1f deg", ImGuiSliderFlags_AlwaysClamp)) {
            light.shapingConeAngle = value;
            changed = true;
        }
        value = float(light.shapingConeSoftness);
        if (ImGui::SliderFloat("softness", &value, 0.0f, float(scene::MaxConeSoftness), "%.2f", ImGuiSliderFlags_AlwaysClamp)) {
            light.shapingConeSoftness = value;
            changed = true;
        }
    }
    if (hasShapeParameter(light, "angle")) {
        value = float(light.angle);
        if (ImGui::SliderFloat("angle", &value, 0.0f, float(scene::MaxDistantAngle), "%.3g deg",
                               ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp)) {
            light.angle = value;
            changed = true;
        }
    }
    return changed;
}

// A shadow-field light's flicker (light_flicker_edit.h); scene time plays it (Space).
bool flickerSliders(hd::LightDesc& light) {
    if (light.kind != hd::LightKind::ShadowField) return false;
    float amplitude = float(light.flicker.amplitude), frequency = float(light.flicker.frequency);
    // The seed as a 32-bit unsigned widget: the scene reader's whole range, kept as it is
    // when only the amplitude or the frequency moves.
    std::uint32_t seed = std::uint32_t(std::min<std::uint64_t>(light.flicker.seed, 0xffffffffu));
    bool changed = ImGui::SliderFloat("flicker amplitude", &amplitude, 0.0f, 1.0f, "%.3f", ImGuiSliderFlags_AlwaysClamp);
    changed |= ImGui::SliderFloat("flicker frequency", &frequency, 0.0f, 1000.0f, "%.3g Hz",
                                  ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    const bool seedChanged = ImGui::InputScalar("flicker seed", ImGuiDataType_U32, &seed);
    if (changed || seedChanged)
        setFlicker(light, amplitude, frequency, seedChanged ? double(seed) : double(light.flicker.seed));
    changed |= seedChanged;
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
    changed |= shapeSliders(light);
    changed |= flickerSliders(light);
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

void drawLightPanel(ViewerModel& model, LightPanelState& state) {
    if (!ImGui::CollapsingHeader("Lights", ImGuiTreeNodeFlags_DefaultOpen)) return;
    std::string& problem = state.problem;
    addButtons(model, state);
    if (!model.selectedLight && !problem.empty()) ImGui::TextWrapped("%s", problem.c_str());
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
