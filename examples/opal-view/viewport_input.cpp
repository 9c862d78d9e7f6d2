#include "examples/opal-view/viewport_input.h"

#include "examples/opal-view/core/edited_scene.h"
#include "examples/opal-view/core/pointer_gestures.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

namespace opal::view {
namespace {

Pointer pointerOf(const ImGuiIO& io) {
    Pointer pointer;
    pointer.x = io.MousePos.x;
    pointer.y = io.MousePos.y;
    pointer.dx = io.MouseDelta.x;
    pointer.dy = io.MouseDelta.y;
    pointer.wheel = io.MouseWheel;
    pointer.left = io.MouseDown[ImGuiMouseButton_Left];
    pointer.middle = io.MouseDown[ImGuiMouseButton_Middle];
    pointer.right = io.MouseDown[ImGuiMouseButton_Right];
    pointer.alt = io.KeyAlt;
    pointer.width = io.DisplaySize.x;
    pointer.height = io.DisplaySize.y;
    return pointer;
}

void dragSelectedLight(ViewerModel& model, const Pointer& pointer) {
    if (!model.selectedLight) return;
    const hd::LightDesc& light = model.light(*model.selectedLight);
    if (light.kind == hd::LightKind::Distant) {
        if (const auto turned = distantLightGesture(model.viewedCamera(), pointer, light)) model.setLight(*model.selectedLight, *turned);
        return;
    }
    if (light.kind != hd::LightKind::Sphere) return;  // point, sphere and spot lights
    if (const auto position = lightGesture(model.viewedCamera(), pointer, lightPosition(light), model.bounds().center))
        model.moveLight(*model.selectedLight, *position);
}

}  // namespace

void handleViewportInput(ViewerModel& model, PanelVisibility& panels) {
    const ImGuiIO& io = ImGui::GetIO();
    // Undo and redo whatever has the keyboard, except a text field (which has its own).
    if (io.KeyCtrl && !io.WantTextInput) {
        if (ImGui::IsKeyPressed(GLFW_KEY_Z, true)) io.KeyShift ? model.redo() : model.undo();
        if (ImGui::IsKeyPressed(GLFW_KEY_Y, true)) model.redo();
    }
    if (!io.WantCaptureKeyboard && !io.KeyCtrl) {
        if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) io.KeyShift ? model.frameAll() : model.frameSelection();
        if (ImGui::IsKeyPressed(GLFW_KEY_R, false)) model.resetCamera();
        if (ImGui::IsKeyPressed(GLFW_KEY_H, false)) panels.help = !panels.help;
        if (ImGui::IsKeyPressed(GLFW_KEY_P, false)) panels.probe = !panels.probe;
        if (ImGui::IsKeyPressed(GLFW_KEY_SPACE, false)) model.playing = !model.playing;
        if (ImGui::IsKeyPressed(GLFW_KEY_G, false)) panels.gizmos = !panels.gizmos;
    }
    if (io.WantCaptureMouse || io.DisplaySize.x <= 0.0f || io.DisplaySize.y <= 0.0f) return;
    const Pointer pointer = pointerOf(io);
    // A gesture through a scene camera moves the free camera from there on (usdview's way).
    OrbitCamera moved = model.viewedCamera();
    if (cameraGesture(moved, pointer)) model.useFreeCamera() = moved;
    dragSelectedLight(model, pointer);
}

}  // namespace opal::view
