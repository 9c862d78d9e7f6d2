#include "examples/opal-view/material_panel.h"

#include <imgui.h>

#include <string>

namespace opal::view {
namespace {

constexpr ImGuiSliderFlags LogSlider = ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp;

void meshPicker(ViewerModel& model) {
    if (model.scene().meshes.size() < 2) return;
    if (!ImGui::BeginCombo("mesh", model.selectedMesh().c_str())) return;
    for (const auto& entry : model.scene().meshes)
        if (ImGui::Selectable(entry.first.c_str(), entry.first == model.selectedMesh())) model.selectMesh(entry.first);
    ImGui::EndCombo();
}

// One slider per channel; true when one moved.
bool channelSliders(const char* label, Rgb& value, double lo, double hi) {
    static constexpr const char* Channels[] = {"R", "G", "B"};
    bool changed = false;
    ImGui::Text("%s (mm^-1), range [%.4g, %.4g]", label, lo, hi);
    for (int c = 0; c < 3; ++c) {
        float v = float(value[c]);
        const std::string id = std::string(Channels[c]) + "##" + label;
        if (ImGui::SliderFloat(id.c_str(), &v, float(lo), float(hi), "%.4g mm^-1", LogSlider)) {
            value[c] = v;
            changed = true;
        }
    }
    return changed;
}

bool scalarSlider(const char* label, double& value, double lo, double hi, const char* format) {
    float v = float(value);
    if (!ImGui::SliderFloat(label, &v, float(lo), float(hi), format, ImGuiSliderFlags_AlwaysClamp)) return false;
    value = v;
    return true;
}

// The measured presets; those outside the asset's editable range are shown but disabled.
void presetPicker(ViewerModel& model) {
    if (!ImGui::BeginCombo("preset", "choose...")) return;
    const EditableRange& range = model.selectedAsset().range;
    for (const NamedMaterial& preset : jensenPresets()) {
        const std::string name(preset.name);
        const bool fits = range.contains(preset.material);
        if (ImGui::Selectable(fits ? name.c_str() : (name + " (outside the asset's range)").c_str(), false,
                              fits ? 0 : ImGuiSelectableFlags_Disabled))
            model.applyPreset(name);
    }
    ImGui::EndCombo();
}

}  // namespace

void drawMaterialPanel(ViewerModel& model) {
    if (!ImGui::CollapsingHeader("Material", ImGuiTreeNodeFlags_DefaultOpen)) return;
    meshPicker(model);
    ImGui::TextDisabled("%s", model.selectedMaterialPath().c_str());
    const EditableRange& range = model.selectedAsset().range;
    hd::MaterialDesc desc = model.selectedMaterial();
    bool changed = channelSliders("sigma_s'", desc.subsurface.sigmaSPrime, range.sigmaSPrimeMin, range.sigmaSPrimeMax);
    changed |= channelSliders("sigma_a", desc.subsurface.sigmaA, range.sigmaAMin, range.sigmaAMax);
    changed |= scalarSlider("eta", desc.subsurface.eta, range.etaMin, range.etaMax, "%.3f");
    changed |= scalarSlider("roughness", desc.specularRoughness, 0.0, 1.0, "%.3f");
    if (changed) model.setSelectedMaterial(desc);
    presetPicker(model);
    if (ImGui::Button("Reset to baked default")) model.resetMaterial();
}

}  // namespace opal::view
