// UsdLux sphere (point, spot) and distant lights reduced to what irradiance needs
// (docs/ARCHITECTURE.md#sphere-light, #distant-light): at a world point, the direction toward the
// light and the irradiance E_perp it gives a surface facing it. The sample's cosine, F_t and
// visibility are applied by the callers.
//
// Units (UsdLux): emitted radiance L_e = color * intensity * 2^exposure, RGB in the working
// space; lengths in scene units.
// - SphereLight, radius r > 0 (world radius: r times the transform's scale): a uniform
//   sphere of radiance L_e, divided by its area 4 pi r^2 when `normalize`. Seen from a
//   point outside it, such a sphere is exactly a point at its centre of radiant intensity
//   I = L_e pi r^2 (while it is wholly above the surface's horizon; nearer the horizon the
//   point form is kept as an approximation). Points inside the sphere receive nothing.
// - SphereLight with treatAsPoint, or r = 0: a point light of radiant intensity I = pi L_e
//   (scene_delegate.h: the intensity is radiant intensity / pi); with `normalize`,
//   I = L_e / 4, the limit of a normalized sphere as r -> 0.
//   Both: E_perp = I / d^2, shadow rays to the sphere's surface (or the point).
// - Shaping (spot): theta_off = the angle between the light's -Z axis and the direction
//   from the light to the point; theta_cut = coneAngle; with s = clamp(coneSoftness, 0, 1),
//   theta_start = (1 - s) theta_cut and the emission is scaled by
//   1 - smoothstep(theta_start, theta_cut, theta_off) (UsdLux ShapingAPI; a hard cut at
//   s = 0: 1 up to theta_cut, 0 beyond).
// - DistantLight: light travels along the transform's -Z axis. The sun-like disk of
//   `angle` degrees (solid angle W = 2 pi (1 - cos(angle / 2))) has radiance L_e, so
//   E_perp = L_e W; with `normalize` (or angle 0) E_perp = L_e: the intensity is the
//   illuminance at normal incidence. The cosine and F_t use the disk's centre direction
//   (the disk is not integrated: its extent changes E by < 1e-5 at 0.53 degrees).
#pragma once

#include "delegate/hd/scene_delegate.h"
#include "delegate/relight/irradiance.h"
#include "schema/scatter/rgb.h"

#include <Imath/ImathVec.h>

#include <optional>
#include <span>
#include <vector>

namespace opal {

class FresnelResponse;
class RayScene;

// What a light delivers at a point.
struct Incidence {
    Imath::V3d toLight;        // unit
    Rgb normalIrradiance;      // E_perp: on a surface facing the light, unshadowed
    double distance = 0.0;     // how far a shadow ray must reach (infinity: distant)
};

class AnalyticLight {
public:
    // Throws opal::Error for a dome or shadow-field light or invalid parameters.
    static AnalyticLight fromDesc(const hd::LightDesc& desc);

    // Nothing when the point receives no light (inside the sphere, outside the cone).
    std::optional<Incidence> incidence(const Imath::V3d& point) const;

private:
    enum class Kind { Point, Distant };
    struct Cone {
        double cutoff = 0.0;       // radians
        double smoothStart = 0.0;  // radians
    };
    double shaping(const Imath::V3d& emission) const;

    Kind kind_ = Kind::Point;
    Imath::V3d position_;  // Point: world position
    Imath::V3d axis_;      // the light's -Z axis in world space: where it shines
    Rgb power_;            // Point: radiant intensity I; Distant: E_perp
    double radius_ = 0.0;  // Point: world radius of the emitting sphere (0 for a point)
    std::optional<Cone> cone_;
};

// One analytic light at every placed sample: the cosine with the sample normal and the
// shadowed E_perp (zero when facing away, outside the light or blocked). Shadow rays start
// `offset` along the normal; scene may be null (no shadows). Parallel over samples.
struct LightArrival {
    float cosTheta = 0.0f;
    Imath::V3f irradiance{0.0f};  // E_perp * visibility (Imath leaves a default vector uninitialized)
};

std::vector<LightArrival> lightArrivals(const AnalyticLight& light, const PlacedSamples& samples,
                                        const RayScene* scene, float offset);

// E_m += E_perp mu h_m(mu) (the moment form, fresnel_response.h).
void addMoments(std::span<const LightArrival> arrivals, const FresnelResponse& response,
                IrradianceMoments& moments);
// E += E_perp F_t(eta, mu) mu, exact (rgb: samples x 3).
void addExactIrradiance(std::span<const LightArrival> arrivals, double eta, std::span<float> rgb);

}  // namespace opal
