#include "examples/opal-view/probe_tooltip.h"

#include "examples/opal-view/core/pixel_probe.h"
#include "schema/error.h"

#include <imgui.h>

#include <cmath>

namespace opal::view {
namespace {

void selectUnder(ViewerModel& model, const std::vector<ProbedAov>& aovs) {
    for (const ProbedAov& aov : aovs) {
        if (aov.aov != "primId" || aov.values.empty()) continue;
        const std::optional<hd::SdfPath> prim = primOfId(model.scene(), model.disabledLights(), aov.values[0]);
        if (!prim) return;
        if (model.scene().meshes.count(*prim)) model.selectMesh(*prim);
        else model.selectedLight = *prim;
    }
}

}  // namespace

void drawProbeTooltip(ViewerModel& model, const Image& shown, const std::string& shownAov) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureMouse || io.DisplaySize.x <= 0.0f || io.DisplaySize.y <= 0.0f) return;
    // Window coordinates to framebuffer pixels (HiDPI), which the renderer draws.
    const int x = int(std::floor(io.MousePos.x * io.DisplayFramebufferScale.x));
    const int y = int(std::floor(io.MousePos.y * io.DisplayFramebufferScale.y));
    PixelProbe probe{x, y, {}, shownAov, shownValue(shown, x, y, model.width(), model.height())};
    try {
        probe.aovs = probeAovs(model.session().buffers(), x, y);
    } catch (const Error&) {
        return;  // outside the picture, or a resize not rendered yet
    }
    ImGui::SetTooltip("%s", probeReport(probe).c_str());
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !io.KeyAlt) selectUnder(model, probe.aovs);
}

}  // namespace opal::view
