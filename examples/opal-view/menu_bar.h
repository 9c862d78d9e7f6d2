// The main menu: File (open a scene or asset layer, open a recent one, save the scene as a
// layer, the picture as a PNG), Edit (undo, redo) and View (the optional panels). Open and
// save ask for the file's path in a small dialog (ImGui has no file browser); what the
// person chose comes back as a request the viewer carries out.
#pragma once

#include "examples/opal-view/core/viewer_model.h"
#include "examples/opal-view/panel_visibility.h"

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace opal::view {

enum class FileAction { Open, SaveScene, SavePicture };

struct FileRequest {
    FileAction action = FileAction::Open;
    std::filesystem::path file;
};

class MenuBar {
public:
    // Draws the menu (and the dialog while open); what the person confirmed this frame.
    // `recent`: File > Open recent, newest first.
    std::optional<FileRequest> draw(ViewerModel& model, PanelVisibility& panels,
                                    const std::vector<std::filesystem::path>& recent);
    // What the last request did ("wrote ...", or the error), shown after the menus.
    std::string status;

private:
    void ask(FileAction action, const std::filesystem::path& suggestion);
    std::optional<FileRequest> fileMenu(const ViewerModel& model, const std::vector<std::filesystem::path>& recent);
    std::optional<FileRequest> dialog();

    std::optional<FileAction> asking_;
    bool openDialog_ = false;
    std::array<char, 1024> path_{};
};

}  // namespace opal::view
