#include "examples/opal-view/core/new_light.h"

#include "examples/opal-view/core/layer_precision.h"

namespace opal::view {
namespace {

constexpr NewLightKind Kinds[] = {NewLightKind::Point, NewLightKind::Sphere, NewLightKind::Spot, NewLightKind::Distant,
                                  NewLightKind::Dome};
constexpr double DistantIntensity = 50000.0;  // UsdLux's DistantLight fallback
constexpr double KeyDistance = 3.0;           // object radii from its centre
constexpr double SphereRadius = 0.25;         // object radii
constexpr double SpotCone = 30.0, SpotSoftness = 0.2;

Imath::V3d keyDirection() { return Imath::V3d(-1.0, 1.2, 1.5).normalized(); }

// A frame whose +Z is `z` (a distant or spot light shines along its -Z).
Imath::M44d facing(const Imath::V3d& z) {
    const Imath::V3d x = Imath::V3d(0.0, 1.0, 0.0).cross(z).normalized(), y = z.cross(x);
    return Imath::M44d(x.x, x.y, x.z, 0.0, y.x, y.y, y.z, 0.0, z.x, z.y, z.z, 0.0, 0.0, 0.0, 0.0, 1.0);
}

// A point light's intensity I gives E = pi I / d^2 (analytic lights); a sphere of radiance
// L and radius r gives E = pi L r^2 / d^2: both pi at the object's centre.
hd::LightDesc keySphere(const BoundingSphere& bounds, bool point) {
    const double distance = KeyDistance * bounds.radius, radius = SphereRadius * bounds.radius;
    hd::LightDesc desc;
    desc.kind = hd::LightKind::Sphere;
    desc.treatAsPoint = point;
    desc.radius = point ? 0.0 : radius;
    desc.intensity = point ? distance * distance : (distance * distance) / (radius * radius);
    desc.transform.setTranslation(bounds.center + keyDirection() * distance);
    return desc;
}

}  // namespace

std::span<const NewLightKind> newLightKinds() { return Kinds; }

std::optional<NewLightKind> newLightKind(std::string_view name) {
    for (const NewLightKind kind : Kinds)
        if (name == newLightKindName(kind)) return kind;
    return std::nullopt;
}

const char* newLightKindName(NewLightKind kind) {
    switch (kind) {
    case NewLightKind::Point: return "point";
    case NewLightKind::Sphere: return "sphere";
    case NewLightKind::Spot: return "spot";
    case NewLightKind::Distant: return "distant";
    case NewLightKind::Dome: return "dome";
    }
    return "";
}

scene::SceneLight newShadowFieldLight(hd::LightDesc baked, const BoundingSphere& bounds) {
    baked.transform = keySphere(bounds, true).transform;
    return {hd::PrimType::ShadowFieldLight, storable(baked), {}};
}

scene::SceneLight newLight(NewLightKind kind, const BoundingSphere& bounds) {
    hd::LightDesc desc;
    switch (kind) {
    case NewLightKind::Point: return {hd::PrimType::SphereLight, storable(keySphere(bounds, true)), {}};
    case NewLightKind::Sphere: return {hd::PrimType::SphereLight, storable(keySphere(bounds, false)), {}};
    case NewLightKind::Spot:
        desc = keySphere(bounds, false);
        desc.transform = facing(keyDirection()) * desc.transform;  // aimed at the centre, then placed
        desc.shapingConeAngle = SpotCone;
        desc.shapingConeSoftness = SpotSoftness;
        return {hd::PrimType::SphereLight, storable(desc), {}};
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
