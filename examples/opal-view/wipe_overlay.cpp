#include "examples/opal-view/wipe_overlay.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace opal::view {
namespace {

constexpr float GrabWidth = 10.0f;  // window pixels the line can be taken by
constexpr float LineWidth = 2.0f;
constexpr ImGuiWindowFlags HandleFlags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground |
                                         ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                         ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoMove;

}  // namespace

int drawWipeLine(WipeState& wipe) {
    const ImGuiIO& io = ImGui::GetIO();
    const float width = io.DisplaySize.x, height = io.DisplaySize.y;
    if (width <= 0.0f || height <= 0.0f) return 0;
    float x = float(wipe.split) * width;
    // A window as thin as the grab strip: hovering it takes the mouse from the viewport.
    ImGui::SetNextWindowPos(ImVec2(x - 0.5f * GrabWidth, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(GrabWidth, height));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0.0f, 0.0f));
    ImGui::Begin("##wipe", nullptr, HandleFlags);
    ImGui::InvisibleButton("##wipe line", ImVec2(GrabWidth, height));
    if (ImGui::IsItemActive()) {
        x = std::clamp(io.MousePos.x, 0.0f, width);
        wipe.split = x / width;
    }
    if (ImGui::IsItemHovered() || ImGui::IsItemActive()) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
    ImGui::End();
    ImGui::PopStyleVar();
    ImGui::GetBackgroundDrawList()->AddLine(ImVec2(x, 0.0f), ImVec2(x, height), IM_COL32(255, 255, 255, 200), LineWidth);
    return int(std::lround(x * io.DisplayFramebufferScale.x));
}

}  // namespace opal::view
