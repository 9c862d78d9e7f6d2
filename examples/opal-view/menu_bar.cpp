#include "examples/opal-view/menu_bar.h"

#include <imgui.h>

namespace opal::view {
namespace {

constexpr const char* DialogName = "File";

std::filesystem::path besideDocument(const ViewerModel& model, const char* suffix) {
    std::filesystem::path file = model.file();
    return file.replace_filename(file.stem().string() + suffix);
}

const char* prompt(FileAction action) {
    switch (action) {
    case FileAction::Open: return "A scene layer or a baked asset layer (.usda):";
    case FileAction::SaveScene: return "The edited scene, as a USDA layer for opal-render:";
    case FileAction::SavePicture: return "The picture as shown, display-referred (.png):";
    }
    return "";
}

}  // namespace

void MenuBar::ask(FileAction action, const std::filesystem::path& suggestion) {
    asking_ = action;
    openDialog_ = true;
    path_.fill('\0');
    suggestion.string().copy(path_.data(), path_.size() - 1);
}

std::optional<FileRequest> MenuBar::fileMenu(const ViewerModel& model, const std::vector<std::filesystem::path>& recent) {
    std::optional<FileRequest> request;
    if (!ImGui::BeginMenu("File")) return request;
    if (ImGui::MenuItem("Open...")) ask(FileAction::Open, model.file());
    if (ImGui::BeginMenu("Open recent", !recent.empty())) {
        for (const std::filesystem::path& file : recent)
            if (ImGui::MenuItem(file.string().c_str())) request = FileRequest{FileAction::Open, file};
        ImGui::EndMenu();
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Save scene as...", nullptr, false, model.isOpen()))
        ask(FileAction::SaveScene, besideDocument(model, ".edited.usda"));
    if (ImGui::MenuItem("Save picture as PNG...", nullptr, false, model.isOpen()))
        ask(FileAction::SavePicture, besideDocument(model, ".png"));
    ImGui::EndMenu();
    return request;
}

std::optional<FileRequest> MenuBar::draw(ViewerModel& model, PanelVisibility& panels,
                                         const std::vector<std::filesystem::path>& recent) {
    std::optional<FileRequest> request;
    if (ImGui::BeginMainMenuBar()) {
        request = fileMenu(model, recent);
        if (ImGui::BeginMenu("Edit")) {
            if (ImGui::MenuItem("Undo", "Ctrl+Z")) model.undo();
            if (ImGui::MenuItem("Redo", "Ctrl+Shift+Z")) model.redo();
            ImGui::EndMenu();
        }
        if (ImGui::BeginMenu("View")) {
            ImGui::MenuItem("Keyboard help", "H", &panels.help);
            ImGui::MenuItem("Pixel probe", "P", &panels.probe);
            ImGui::MenuItem("Light gizmos", "G", &panels.gizmos);
            ImGui::MenuItem("Render stats", nullptr, &panels.stats);
            ImGui::MenuItem("Render settings", nullptr, &panels.settings);
            ImGui::MenuItem("Render delegates", nullptr, &panels.delegates);
            ImGui::EndMenu();
        }
        if (!status.empty()) ImGui::TextDisabled("  %s", status.c_str());
        ImGui::EndMainMenuBar();
    }
    if (std::optional<FileRequest> confirmed = dialog()) request = std::move(confirmed);
    return request;
}

std::optional<FileRequest> MenuBar::dialog() {
    if (openDialog_) ImGui::OpenPopup(DialogName);
    openDialog_ = false;
    if (!ImGui::BeginPopupModal(DialogName, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return std::nullopt;
    std::optional<FileRequest> request;
    ImGui::TextUnformatted(prompt(*asking_));
    ImGui::SetNextItemWidth(480.0f);
    const bool entered = ImGui::InputText("##path", path_.data(), path_.size(), ImGuiInputTextFlags_EnterReturnsTrue);
    if (ImGui::Button(*asking_ == FileAction::Open ? "Open" : "Save") || entered) {
        request = FileRequest{*asking_, std::filesystem::path(path_.data())};
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return request;
}

}  // namespace opal::view
