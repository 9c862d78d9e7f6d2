#include "examples/opal-view/camera_panel.h"

#include <imgui.h>

#include <cmath>
#include <numbers>

namespace opal::view {

void drawCameraPanel(ViewerModel& model) {
    if (!ImGui::CollapsingHeader("Camera")) return;
    float focal = float(model.camera.focalLength);
    if (ImGui::SliderFloat("focal length", &focal, 10.0f, 300.0f, "%.1f mm",
                           ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
        setFocalLength(model.camera, focal);
    const Imath::V2d film = visibleFilm(model.camera, model.aspect());
    const double fov = 2.0 * std::atan(0.5 * film.x / model.camera.focalLength) * 180.0 / std::numbers::pi;
    ImGui::Text("horizontal field of view %.1f deg", fov);
    if (ImGui::Button("Frame all (F)")) model.frameAll();
    ImGui::SameLine();
    if (ImGui::Button("Reset (R)")) model.resetCamera();
}

}  // namespace opal::view
