#include "examples/opal-view/delegate_panels.h"

#include <imgui.h>

#include <array>
#include <cstdio>
#include <optional>
#include <variant>

namespace opal::view {
namespace {

std::string text(const hd::Value& value) {
    if (const bool* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
    if (const int* i = std::get_if<int>(&value)) return std::to_string(*i);
    if (const double* d = std::get_if<double>(&value)) {
        char number[32];
        std::snprintf(number, sizeof number, "%.4g", *d);
        return number;
    }
    if (const std::string* s = std::get_if<std::string>(&value)) return *s;
    return "(other)";
}

// The setting's control; the new value when it was changed this frame.
std::optional<hd::Value> control(const hd::RenderSettingDescriptor& setting, const hd::Value& value) {
    const char* label = setting.name.empty() ? setting.key.c_str() : setting.name.c_str();
    if (const bool* b = std::get_if<bool>(&value)) {
        bool on = *b;
        if (ImGui::Checkbox(label, &on)) return hd::Value(on);
    } else if (const int* i = std::get_if<int>(&value)) {
        int v = *i;
        const int lo = int(setting.min.value_or(0.0)), hi = int(setting.max.value_or(1000.0));
        if (ImGui::SliderInt(label, &v, lo, hi, "%d", ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic))
            return hd::Value(v);
    } else if (const double* d = std::get_if<double>(&value)) {
        float v = float(*d);
        if (ImGui::SliderFloat(label, &v, float(setting.min.value_or(0.0)), float(setting.max.value_or(1.0))))
            return hd::Value(double(v));
    } else if (const std::string* s = std::get_if<std::string>(&value)) {
        if (!setting.choices.empty()) {
            std::optional<hd::Value> chosen;
            if (ImGui::BeginCombo(label, s->c_str())) {
                for (const std::string& choice : setting.choices)
                    if (ImGui::Selectable(choice.c_str(), choice == *s)) chosen = hd::Value(choice);
                ImGui::EndCombo();
            }
            return chosen;
        }
        std::array<char, 1024> buffer{};
        s->copy(buffer.data(), buffer.size() - 1);
        if (ImGui::InputText(label, buffer.data(), buffer.size(), ImGuiInputTextFlags_EnterReturnsTrue))
            return hd::Value(std::string(buffer.data()));
    }
    if (ImGui::IsItemHovered() && !setting.help.empty()) ImGui::SetTooltip("%s: %s", setting.key.c_str(), setting.help.c_str());
    return std::nullopt;
}

}  // namespace

void drawStatsPanel(const hd::RenderDelegate& delegate, bool& open) {
    if (!open) return;
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - 350.0f, 30.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(340.0f, 360.0f), ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Render stats", &open) && ImGui::BeginTable("##stats", 2, ImGuiTableFlags_RowBg)) {
        for (const auto& [name, value] : delegate.renderStats()) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(name.c_str());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(text(value).c_str());
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

void drawRenderSettingsPanel(ViewerModel& model, const hd::RenderDelegate& delegate, bool& open, std::string& problem) {
    if (!open) return;
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - 390.0f, 400.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(380.0f, 0.0f), ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Render settings", &open)) {
        for (const hd::RenderSettingDescriptor& setting : delegate.renderSettingDescriptors()) {
            const std::optional<hd::Value> changed = control(setting, model.renderSetting(setting.key));
            if (!changed) continue;
            try {
                model.setRenderSetting(setting.key, *changed);
                problem.clear();
            } catch (const std::exception& e) {
                problem = e.what();
            }
        }
        if (!problem.empty()) ImGui::TextWrapped("%s", problem.c_str());
    }
    ImGui::End();
}

}  // namespace opal::view
