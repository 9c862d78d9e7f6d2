#include "examples/opal-view/camera_panel.h"

#include <imgui.h>

#include <algorithm>

namespace opal::view {
namespace {

constexpr const char* FreeCamera = "free camera";

// The scene's cameras and the free one; picking a scene camera looks through it.
void drawCameraPicker(ViewerModel& model) {
    const std::optional<hd::SdfPath>& used = model.usedCamera();
    if (!ImGui::BeginCombo("camera", used ? used->c_str() : FreeCamera)) return;
    if (ImGui::Selectable(FreeCamera, !used) && used) model.useFreeCamera();
    for (const hd::SdfPath& path : model.sceneCameras())
        if (ImGui::Selectable(path.c_str(), used == path)) model.useCamera(path);
    ImGui::EndCombo();
}

// Lens and clipping of what the viewport looks through; an edit goes to the free camera.
void drawLens(ViewerModel& model) {
    const OrbitCamera viewed = model.viewedCamera();
    float focal = float(viewed.focalLength);
    if (ImGui::SliderFloat("focal length", &focal, 10.0f, 300.0f, "%.1f mm",
                           ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
        setFocalLength(model.useFreeCamera(), focal);
    float fov = float(horizontalFieldOfView(viewed, model.aspect()));
    if (ImGui::SliderFloat("field of view", &fov, 5.0f, 150.0f, "%.1f deg", ImGuiSliderFlags_AlwaysClamp))
        setHorizontalFieldOfView(model.useFreeCamera(), fov, model.aspect());
}

void drawClipping(ViewerModel& model) {
    bool automatic = !model.camera.nearClip;
    if (ImGui::Checkbox("automatic clipping", &automatic)) {
        if (automatic) setAutomaticClipping(model.useFreeCamera());
        else {
            const hd::CameraDesc now = cameraDesc(model.viewedCamera(), model.bounds());
            setClipping(model.useFreeCamera(), now.nearClip, now.farClip);
        }
    }
    if (automatic) return;
    float range[2] = {float(*model.camera.nearClip), float(*model.camera.farClip)};
    const float speed = std::max(range[1] * 0.005f, 1e-4f);
    if (ImGui::DragFloat2("near, far", range, speed, 0.0f, 0.0f, "%.4g") && range[0] > 0.0f && range[1] > range[0])
        setClipping(model.useFreeCamera(), range[0], range[1]);
}

}  // namespace

void drawCameraPanel(ViewerModel& model) {
    if (!ImGui::CollapsingHeader("Camera")) return;
    drawCameraPicker(model);
    drawLens(model);
    drawClipping(model);
    if (ImGui::Button("Frame selection (F)")) model.frameSelection();
    ImGui::SameLine();
    if (ImGui::Button("Frame all (Shift+F)")) model.frameAll();
    ImGui::SameLine();
    if (ImGui::Button("Reset (R)")) model.resetCamera();
}

}  // namespace opal::view
