#include "examples/opal-view/light_gizmo_overlay.h"

#include "examples/opal-view/core/light_gizmos.h"

#include <imgui.h>

#include <cmath>

namespace opal::view {
namespace {

constexpr float MarkerRadius = 7.0f, RingRadius = 11.0f, ArrowWidth = 3.0f, HeadLength = 14.0f;
const ImU32 Rim = IM_COL32(16, 16, 16, 255);

ImU32 colorOf(bool selected) {
    const auto& c = selected ? kSelectedGizmoColor : kGizmoColor;
    return IM_COL32(c[0], c[1], c[2], 255);
}

ImVec2 point(const Imath::V2d& p) { return ImVec2(float(p.x), float(p.y)); }

void drawMarker(ImDrawList& draw, const LightGizmo& gizmo) {
    const ImVec2 at = point(gizmo.at);
    draw.AddCircleFilled(at, MarkerRadius + 1.5f, Rim);
    draw.AddCircleFilled(at, MarkerRadius, colorOf(gizmo.selected));
    if (gizmo.selected) draw.AddCircle(at, RingRadius, colorOf(true), 0, 2.0f);
}

void drawArrow(ImDrawList& draw, const LightGizmo& gizmo) {
    const Imath::V2d along = gizmo.at - gizmo.from;
    const double length = along.length();
    if (length < 1e-3) return drawMarker(draw, gizmo);  // seen end on: a marker
    const Imath::V2d unit = along / length, side(-unit.y, unit.x);
    const Imath::V2d base = gizmo.at - unit * std::min(double(HeadLength), length);
    const ImU32 color = colorOf(gizmo.selected);
    draw.AddLine(point(gizmo.from), point(base), color, gizmo.selected ? ArrowWidth + 1.0f : ArrowWidth);
    draw.AddTriangleFilled(point(gizmo.at), point(base + side * (0.5 * HeadLength)), point(base - side * (0.5 * HeadLength)),
                           color);
}

}  // namespace

void drawLightGizmos(const ViewerModel& model) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.DisplaySize.x <= 0.0f || io.DisplaySize.y <= 0.0f) return;
    const OrbitCamera camera = model.viewedCamera();
    const GizmoView view{&camera, io.DisplaySize.x, io.DisplaySize.y, model.bounds(), model.selectedLight};
    ImDrawList& draw = *ImGui::GetBackgroundDrawList();
    for (const LightGizmo& gizmo : lightGizmos(model.scene(), view)) {
        if (gizmo.shape == LightGizmo::Shape::Arrow) drawArrow(draw, gizmo);
        else drawMarker(draw, gizmo);
    }
}

}  // namespace opal::view
