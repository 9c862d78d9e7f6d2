// The pull interface a scene source implements (Hydra's HdSceneDelegate): prims ask it for
// their data during Sync. The delegate knows nothing of files; a scene source (a USDA
// scene reader, a viewer, a test) loads assets and answers with these descriptions.
// Conventions: transforms map object space to world space, row-vector convention as in
// Imath and USD (p_world = p_object * M); world space is right-handed, Y up unless the
// scene says otherwise; lengths in scene units.
#pragma once

#include "delegate/hd/types.h"
#include "schema/asset/translucent_asset.h"
#include "schema/scatter/material.h"
#include "schema/scatter/rgb.h"

#include <Imath/ImathMatrix.h>

#include <cstdint>
#include <memory>
#include <optional>

namespace opal::hd {

struct MeshDesc {
    std::shared_ptr<const TranslucentAsset> asset;  // baked data; never null for a valid mesh
    Imath::M44d transform;                          // object to world
    SdfPath material;                               // empty: the asset's default material
    bool visible = true;
};

// Material override (Opal's material prim): the subsurface coefficients in mm^-1 and the
// specular layer. Colors are in the working space.
//
// Defaults of what a layer holds as a float attribute are float values here too (0.35f, not
// 0.35): a value left at its default is saved as the float it is, and a scene that omits an
// attribute then renders bit for bit as one that authors its default. With double defaults
// the viewer's saved picture and opal-render's of the saved layer differed by a float step
// in every specular pixel (tests/view/save_test.cpp).
inline constexpr double kDefaultSpecularRoughness = 0.35f;

struct MaterialDesc {
    Material subsurface;
    bool specular = true;          // a Fresnel-weighted GGX layer
    double specularRoughness = kDefaultSpecularRoughness;
};

enum class LightKind { Sphere, Distant, Dome, ShadowField };

// A shadow-field light's flicker (delegate/relight/light_flicker.h): amplitude 0 is none.
struct LightFlicker {
    double amplitude = 0.0;
    double frequency = 8.0;  // Hz
    std::uint64_t seed = 0;
};

// UsdLux semantics: emitted radiance = color * intensity * 2^exposure, times the black
// body colour of colorTemperature (kelvin, unit luminance in ACEScg) when
// enableColorTemperature is on; with `normalize` a
// sphere light's power does not depend on its size. A sphere with treatAsPoint is a
// point light whose intensity is radiant intensity / pi (as UsdLux's "treat as point").
// Shaping (a spot): a cone of coneAngle degrees around the light's -Z axis, softened by
// coneSoftness in [0, 1]. A distant light shines along its -Z axis over a cone of `angle`
// degrees. A dome reads a lat-long image (textureFile), +Y up, rotated by its transform.
struct LightDesc {
    LightKind kind = LightKind::Sphere;
    Imath::M44d transform;
    Rgb color{1.0, 1.0, 1.0};
    double intensity = 1.0;
    double exposure = 0.0;
    bool enableColorTemperature = false;
    double colorTemperature = 6500.0;  // kelvin, 500 to 40000 (UsdLux's fallback 6500)
    bool normalize = false;
    // SphereLight
    double radius = 0.5;
    bool treatAsPoint = false;
    std::optional<double> shapingConeAngle;  // degrees; set for a spot light
    double shapingConeSoftness = 0.0;
    // DistantLight
    double angle = 0.53f;  // degrees (a float default: see MaterialDesc)
    // DomeLight
    std::string textureFile;
    std::string textureColorSpace = "Linear Rec.709 (sRGB)";
    bool visibleToCamera = true;
    // ShadowFieldLight: the light asset's sidecar (the baked source radiance field), its
    // flicker, and the scene time (seconds) the flicker is evaluated at.
    std::string shadowField;
    LightFlicker flicker;
    double time = 0.0;
};

// UsdGeomCamera: a perspective camera looking down its -Z axis; focal length and apertures
// share one unit (only their ratio matters).
struct CameraDesc {
    Imath::M44d transform;  // camera to world
    double focalLength = 50.0;
    double horizontalAperture = 36.0;
    double verticalAperture = 24.0;
    double nearClip = 0.1f, farClip = 1.0e6;  // float defaults: see MaterialDesc
};

class SceneDelegate {
public:
    virtual ~SceneDelegate() = default;
    virtual MeshDesc mesh(const SdfPath& id) const = 0;
    virtual MaterialDesc material(const SdfPath& id) const = 0;
    virtual LightDesc light(const SdfPath& id) const = 0;
    virtual CameraDesc camera(const SdfPath& id) const = 0;
};

}  // namespace opal::hd
