#include "examples/opal-view/menu_bar.h"

#include <imgui.h>

namespace opal::view {
namespace {

constexpr const char* DialogName = "Save as";

std::filesystem::path besideDocument(const ViewerModel& model, const char* suffix) {
    std::filesystem::path file = model.file();
    return file.replace_filename(file.stem().string() + suffix);
}

}  // namespace

void MenuBar::ask(SaveKind kind, const std::filesystem::path& suggestion) {
    asking_ = kind;
    openDialog_ = true;
    path_.fill('\0');
    suggestion.string().copy(path_.data(), path_.size() - 1);
}

std::optional<SaveRequest> MenuBar::draw(ViewerModel& model, PanelVisibility& panels) {
    if (ImGui::BeginMainMenuBar()) {
        if (ImGui::BeginMenu("File")) {
            if (ImGui::MenuItem("Save scene as...", nullptr, false, model.isOpen()))
                ask(SaveKind::Scene, besideDocument(model, ".edited.usda"));
            if (ImGui::MenuItem("Save picture as PNG...", nullptr, false, model.isOpen()))
                ask(SaveKind::Picture, besideDocument(model, ".png"));
            ImGui::EndMenu();
        }
        if (ImGui::BeginMenu("Edit")) {
            if (ImGui::MenuItem("Undo", "Ctrl+Z")) model.undo();
            if (ImGui::MenuItem("Redo", "Ctrl+Shift+Z")) model.redo();
            ImGui::EndMenu();
        }
        if (ImGui::BeginMenu("View")) {
            ImGui::MenuItem("Keyboard help", "H", &panels.help);
            ImGui::MenuItem("Pixel probe", "P", &panels.probe);
            ImGui::MenuItem("Render stats", nullptr, &panels.stats);
            ImGui::MenuItem("Render settings", nullptr, &panels.settings);
            ImGui::EndMenu();
        }
        if (!status.empty()) ImGui::TextDisabled("  %s", status.c_str());
        ImGui::EndMainMenuBar();
    }
    return dialog();
}

std::optional<SaveRequest> MenuBar::dialog() {
    if (openDialog_) ImGui::OpenPopup(DialogName);
    openDialog_ = false;
    if (!ImGui::BeginPopupModal(DialogName, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return std::nullopt;
    std::optional<SaveRequest> request;
    ImGui::TextUnformatted(*asking_ == SaveKind::Scene ? "The edited scene, as a USDA layer for opal-render:"
                                                       : "The picture as shown, display-referred:");
    ImGui::SetNextItemWidth(480.0f);
    const bool entered = ImGui::InputText("##path", path_.data(), path_.size(), ImGuiInputTextFlags_EnterReturnsTrue);
    if (ImGui::Button("Save") || entered) {
        request = SaveRequest{*asking_, std::filesystem::path(path_.data())};
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return request;
}

}  // namespace opal::view
