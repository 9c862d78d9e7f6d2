#include "examples/opal-view/viewport_input.h"

#include "examples/opal-view/core/edited_scene.h"
#include "examples/opal-view/core/light_drag.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

namespace opal::view {
namespace {

constexpr double DollyPixelsPerStep = 20.0;

void moveCamera(ViewerModel& model, const ImGuiIO& io) {
    const double dx = io.MouseDelta.x, dy = io.MouseDelta.y;
    if (io.MouseDown[ImGuiMouseButton_Left]) tumble(model.camera, dx, dy);
    else if (io.MouseDown[ImGuiMouseButton_Middle]) track(model.camera, dx, dy, int(io.DisplaySize.y), model.aspect());
    else if (io.MouseDown[ImGuiMouseButton_Right]) dolly(model.camera, (dx - dy) / DollyPixelsPerStep);
}

void dragLight(ViewerModel& model, const ImGuiIO& io) {
    if (!model.selectedLight || !io.MouseDown[ImGuiMouseButton_Left]) return;
    if (io.MouseDelta.x == 0.0f && io.MouseDelta.y == 0.0f) return;
    const hd::LightDesc& light = model.light(*model.selectedLight);
    if (light.kind != hd::LightKind::Sphere) return;
    const double ndcX = 2.0 * io.MousePos.x / io.DisplaySize.x - 1.0;
    const double ndcY = 1.0 - 2.0 * io.MousePos.y / io.DisplaySize.y;
    const Imath::V3d center = model.bounds().center;
    const double radius = (lightPosition(light) - center).length();
    const Imath::V3d ray = viewRay(model.camera, model.aspect(), ndcX, ndcY);
    model.moveLight(*model.selectedLight, pointOnSphere(eyePosition(model.camera), ray, center, radius));
}

}  // namespace

void handleViewportInput(ViewerModel& model) {
    const ImGuiIO& io = ImGui::GetIO();
    if (!io.WantCaptureKeyboard) {
        if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) model.frameAll();
        if (ImGui::IsKeyPressed(GLFW_KEY_R, false)) model.resetCamera();
    }
    if (io.WantCaptureMouse || io.DisplaySize.x <= 0.0f || io.DisplaySize.y <= 0.0f) return;
    if (io.MouseWheel != 0.0f) dolly(model.camera, io.MouseWheel);
    if (io.KeyAlt) moveCamera(model, io);
    else dragLight(model, io);
}

}  // namespace opal::view
