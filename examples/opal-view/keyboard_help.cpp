#include "examples/opal-view/keyboard_help.h"

#include <imgui.h>

namespace opal::view {
namespace {

struct Shortcut {
    const char* keys;
    const char* what;
};

constexpr Shortcut Shortcuts[] = {
    {"Alt + left drag", "tumble the camera about its target"},
    {"Alt + middle drag", "track (slide the camera and its target)"},
    {"Alt + right drag, wheel", "dolly"},
    {"left drag", "move the selected point, sphere or spot light around the object; turn a distant light"},
    {"left click (probe on)", "select the asset or shadow-field light under the cursor"},
    {"F", "frame the selected asset"},
    {"Shift+F", "frame everything"},
    {"R", "reset the camera (the free one, where the file opened)"},
    {"P", "pixel probe: every AOV's value under the cursor"},
    {"Space", "play or pause scene time (animated lights and transforms, flicker)"},
    {"G", "light gizmos: where each light is, an arrow for a distant light"},
    {"W", "A/B wipe: the engine left of the line, the exact reference right (drag the line)"},
    {"Ctrl+Z", "undo a material or light edit"},
    {"Ctrl+Shift+Z, Ctrl+Y", "redo"},
    {"H", "this help"},
};

}  // namespace

void drawKeyboardHelp(bool& open) {
    if (!open) return;
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowBgAlpha(0.85f);
    if (ImGui::Begin("Keyboard and mouse", &open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings) &&
        ImGui::BeginTable("##shortcuts", 2)) {
        for (const Shortcut& shortcut : Shortcuts) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(shortcut.keys);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(shortcut.what);
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

}  // namespace opal::view
