#include "examples/opal-view/hud.h"

#include <imgui.h>

#include <variant>

namespace opal::view {
namespace {

template <class T>
T stat(const std::map<hd::Token, hd::Value>& values, const char* name, T fallback) {
    const auto it = values.find(name);
    const T* value = it == values.end() ? nullptr : std::get_if<T>(&it->second);
    return value ? *value : fallback;
}

struct SceneSize {
    std::size_t samples = 0, triangles = 0;
};

SceneSize sceneSize(const scene::Scene& scene) {
    SceneSize size;
    for (const auto& [path, mesh] : scene.meshes) {
        size.samples += mesh.desc.asset->samples.size();
        for (const std::int32_t n : mesh.desc.asset->mesh.faceVertexCounts) size.triangles += std::size_t(std::max(n - 2, 0));
    }
    return size;
}

}  // namespace

void drawHud(const ViewerModel& model, const HudFigures& figures) {
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(10.0f, io.DisplaySize.y - 10.0f), ImGuiCond_Always, ImVec2(0.0f, 1.0f));
    ImGui::SetNextWindowBgAlpha(0.5f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoSavedSettings;
    if (!ImGui::Begin("##hud", nullptr, flags)) return ImGui::End();
    const hd::RenderDelegate& delegate = model.session().delegate();
    const auto stats = delegate.renderStats();
    const SessionStatus status = model.session().status();
    const SceneSize size = sceneSize(model.scene());
    const int target = stat(delegate.renderSettings(), "opal:samplesPerPixel", 0);
    const double fps = figures.frameMs > 0.0 ? 1000.0 / figures.frameMs : 0.0;
    ImGui::Text("%.0f fps (draw %.1f ms) | relight %.1f ms%s | %d / %d spp%s | %zu samples, %zu triangles", fps,
                figures.drawMs, status.lastSyncMs, status.busy ? " (relighting)" : "", stat(stats, "samplesPerPixel", 0), target,
                stat(stats, "converged", false) ? " converged" : "", size.samples, size.triangles);
    if (model.animated())
        ImGui::Text("time code %.2f (%.3f s)%s", model.timeCode(), model.timeCode() / model.scene().timeCodesPerSecond,
                    model.playing ? " playing (Space pauses)" : " paused (Space plays)");
    if (!figures.message.empty()) ImGui::TextWrapped("%s", figures.message.c_str());
    ImGui::End();
}

}  // namespace opal::view
