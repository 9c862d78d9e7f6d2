// The main menu: File (save the scene as a layer, the picture as a PNG), Edit (undo, redo)
// and View (the optional panels). A save asks for the file's path in a small dialog (ImGui
// has no file browser) and comes back as a request the viewer carries out.
#pragma once

#include "examples/opal-view/core/viewer_model.h"
#include "examples/opal-view/panel_visibility.h"

#include <array>
#include <filesystem>
#include <optional>
#include <string>

namespace opal::view {

enum class SaveKind { Scene, Picture };

struct SaveRequest {
    SaveKind kind = SaveKind::Scene;
    std::filesystem::path file;
};

class MenuBar {
public:
    // Draws the menu (and the dialog while open); a save the person confirmed this frame.
    std::optional<SaveRequest> draw(ViewerModel& model, PanelVisibility& panels);
    // What the last save did ("wrote ...", or the error), shown in the dialog's place.
    std::string status;

private:
    void ask(SaveKind kind, const std::filesystem::path& suggestion);
    std::optional<SaveRequest> dialog();

    std::optional<SaveKind> asking_;
    bool openDialog_ = false;
    std::array<char, 1024> path_{};
};

}  // namespace opal::view
