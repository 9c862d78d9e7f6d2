#include "examples/opal-view/material_panel.h"

#include "schema/error.h"

#include <imgui.h>

#include <string>
#include <string_view>

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

// The artist's parameters (Jensen and Buhler 2002): the total diffuse reflectance per
// channel as a colour, and the diffuse mean free path per channel in mm. An edit converts
// to sigma_s' and sigma_a (material_edit.h); one outside the asset's range is refused and
// shown.
void artistControls(ViewerModel& model, std::string& problem) {
    const ArtistMaterial artist = toArtist(model.selectedMaterial().subsurface);
    float albedo[3] = {float(artist.albedo[0]), float(artist.albedo[1]), float(artist.albedo[2])};
    float mfp[3] = {float(artist.meanFreePath[0]), float(artist.meanFreePath[1]), float(artist.meanFreePath[2])};
    const char* parameter = nullptr;
    if (ImGui::ColorEdit3("albedo", albedo, ImGuiColorEditFlags_Float)) parameter = "albedo";
    if (ImGui::DragFloat3("mean free path (mm)", mfp, 0.01f, 1e-3f, 1e3f, "%.4g", LogSlider)) parameter = "mfp";
    if (!parameter) return;
    const float* edited = parameter == std::string_view("albedo") ? albedo : mfp;
    const double values[] = {edited[0], edited[1], edited[2]};
    try {
        model.setMaterialParameter(parameter, values);
        problem.clear();
    } catch (const Error& e) {
        problem = e.what();
    }
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

void drawMaterialPanel(ViewerModel& model, MaterialPanelState& state) {
    if (!ImGui::CollapsingHeader("Material", ImGuiTreeNodeFlags_DefaultOpen)) return;
    meshPicker(model);
    ImGui::TextDisabled("%s", model.selectedMaterialPath().c_str());
    const EditableRange& range = model.selectedAsset().range;
    ImGui::Checkbox("albedo + mean free path", &state.artist);
    if (state.artist) {
        artistControls(model, state.problem);
        if (!state.problem.empty()) ImGui::TextWrapped("%s", state.problem.c_str());
    }
    hd::MaterialDesc desc = model.selectedMaterial();
    bool changed = false;
    if (!state.artist) {
        changed |= channelSliders("sigma_s'", desc.subsurface.sigmaSPrime, range.sigmaSPrimeMin, range.sigmaSPrimeMax);
        changed |= channelSliders("sigma_a", desc.subsurface.sigmaA, range.sigmaAMin, range.sigmaAMax);
    }
    changed |= scalarSlider("eta", desc.subsurface.eta, range.etaMin, range.etaMax, "%.3f");
    changed |= scalarSlider("roughness", desc.specularRoughness, 0.0, 1.0, "%.3f");
    if (changed) model.setSelectedMaterial(desc);
    presetPicker(model);
    if (ImGui::Button("Reset to baked default")) model.resetMaterial();
}

}  // namespace opal::view
