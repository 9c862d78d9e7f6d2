#include "examples/opal-view/core/new_light.h"

#include "examples/opal-view/core/layer_precision.h"

namespace opal::view {
namespace {

constexpr NewLightKind Kinds[] = {NewLightKind::Point, NewLightKind::Distant, NewLightKind::Dome};
constexpr double DistantIntensity = 50000.0;  // UsdLux's DistantLight fallback

Imath::V3d keyDirection() { return Imath::V3d(-1.0, 1.2, 1.5).normalized(); }

// A frame whose +Z is `z` (a distant light shines along its -Z).
Imath::M44d facing(const Imath::V3d& z) {
    const Imath::V3d x = Imath::V3d(0.0, 1.0, 0.0).cross(z).normalized(), y = z.cross(x);
    return Imath::M44d(x.x, x.y, x.z, 0.0, y.x, y.y, y.z, 0.0, z.x, z.y, z.z, 0.0, 0.0, 0.0, 0.0, 1.0);
}

}  // namespace

std::optional<NewLightKind> newLightKind(std::string_view name) {
    for (const NewLightKind kind : Kinds)
        if (name == newLightKindName(kind)) return kind;
    return std::nullopt;
}

const char* newLightKindName(NewLightKind kind) {
    switch (kind) {
    case NewLightKind::Point: return "point";
    case NewLightKind::Distant: return "distant";
    case NewLightKind::Dome: return "dome";
    }
    return "";
}

scene::SceneLight newLight(NewLightKind kind, const BoundingSphere& bounds) {
    hd::LightDesc desc;
    switch (kind) {
    case NewLightKind::Point: {
        const double distance = 3.0 * bounds.radius;
        desc.kind = hd::LightKind::Sphere;
        desc.treatAsPoint = true;
        desc.radius = 0.0;
        desc.intensity = distance * distance;
        desc.transform.setTranslation(bounds.center + keyDirection() * distance);
        return {hd::PrimType::SphereLight, storable(desc), {}};
    }
    case NewLightKind::Distant:
        desc.kind = hd::LightKind::Distant;
        desc.intensity = DistantIntensity;
        desc.transform = facing(keyDirection());
        return {hd::PrimType::DistantLight, storable(desc), {}};
    case NewLightKind::Dome: desc.kind = hd::LightKind::Dome; return {hd::PrimType::DomeLight, storable(desc), {}};
    }
    return {};
}

}  // namespace opal::view
