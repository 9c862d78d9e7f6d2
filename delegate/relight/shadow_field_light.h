// A shadow-field local light (Zhou et al. 2005; docs/ARCHITECTURE.md#shadow-field-light): a
// baked source radiance field (schema/asset/shadow_field.h) placed in the world by the
// prim's transform and scaled by its color * intensity * 2^exposure (times its flicker at
// the scene time, light_flicker.h).
//
// At a sample x with normal n (both taken into the light's frame, mm):
//   - inside the field (and inside its inner sphere: the nearest shell), the incident
//     radiance cube map L_k(x) of ShadowFieldLookup, and
//         E(x) = sum_k L_k W_k(n) V_k(x),
//     W_k(n) the texel's clamped-cosine integral (cube_map_cosine.h) and V_k the visibility
//     toward the emitter along texel k. V_k is traced, distance-aware: one occlusion ray per
//     lit block of 4 x 4 texels, along the block's irradiance-weighted direction, ending
//     where that ray enters the emitter's bounding sphere (a sample's rays go to Embree
//     together, as coherent packets). A blocker beyond the emitter
//     (the far rim of a melted candle, seen past the flame) therefore never shadows it;
//     the emitter itself is not in the ray scene and never blocks. The faintest blocks,
//     together under 2% of the sample's light, trace no ray and take the visible fraction
//     of the traced blocks' light.
//   - a sample with the emitter's whole bounding sphere behind its tangent plane: 0,
//     without a lookup (exact: it sees no point of the emitter).
//   - beyond the outer sphere, the field's far-field point light: E_perp = I(w) / r^2 with
//     one occlusion ray to the emitter's bounding sphere (I(w) blended from a table made when
//     the field loads; a chunk's rays traced together as packets).
// What the irradiance moments need is one direction per sample: the light arrives over the
// emitter's solid angle, so the sample keeps mu_eff, the irradiance-weighted mean cosine,
// and E_perp = E / mu_eff. The cosine is then exact (E is), and F_t(eta, mu) is taken at
// mu_eff (F_t varies slowly away from grazing; the reference mode uses the same E and
// mu_eff, so it checks the transfer, not this step).
//
// For the specular layer the light is the sphere light of the emitter's bounding radius
// and its mean far-field intensity; the camera sees the emitter through its baked views.
#pragma once

#include "delegate/hd/scene_delegate.h"
#include "delegate/relight/analytic_light.h"
#include "delegate/relight/irradiance.h"
#include "delegate/relight/shadow_field_stages.h"
#include "delegate/relight/sparse_field_maps.h"
#include "schema/asset/cube_map_cosine.h"
#include "schema/asset/shadow_field_lookup.h"

#include <Imath/ImathMatrix.h>
#include <Imath/ImathVec.h>

#include <memory>
#include <vector>

namespace opal {

class RayScene;

// A baked field with what evaluating it needs, shared by every light prim that uses the file.
struct LoadedShadowField {
    ShadowField field;
    ShadowFieldLookup lookup;
    // Irradiance is formed on the maps averaged to half their face size (16 for the shipped
    // 32): a quarter of the texels to synthesize and weigh, each with its exact cosine
    // integral; what is lost is only the product of radiance and cosine varying together
    // inside a 2 x 2 texel block.
    CubeMapLayout layout;
    CubeMapCosineIntegral cosine;
    SparseFieldMaps maps;  // every map at `layout`'s face size, its nonzero texels
    Imath::V3d meanIntensity{0.0};  // of the far-field point light, over all directions
    // The far-field intensity I(w) at each of the outer shell's sample directions
    // (ShadowFieldLookup::farIntensity there): beyond the field a sample blends these with
    // the stencil's weights instead of blending and integrating the maps, the same up to
    // where the maps' ringing is clamped (each map's own, rather than the blend's).
    std::vector<Imath::V3d> farIntensities;
    Imath::V3d farIntensity(const FieldStencil& beyond) const;
    // Per texel of `layout`: its centre direction, and its visibility block (2 x 2 texels of
    // `layout`, 4 x 4 of the maps), side by side for the per-sample loop.
    struct Texel {
        Imath::V3f direction;
        std::uint32_t block = 0;
    };
    std::vector<Texel> texels;
    std::uint32_t blocks = 0;

    explicit LoadedShadowField(ShadowField f);
    LoadedShadowField(const LoadedShadowField&) = delete;
    LoadedShadowField& operator=(const LoadedShadowField&) = delete;
};

class ShadowFieldLight {
public:
    // Throws opal::Error for a desc that is not a shadow-field light, a transform that is not
    // rotation x uniform scale x translation, or invalid emission.
    ShadowFieldLight(std::shared_ptr<const LoadedShadowField> field, const hd::LightDesc& desc);

    // The shadowed irradiance at each placed sample, in the one-direction form of
    // LightArrival (mu_eff, E / mu_eff). Shadow rays start `offset` along the normal; scene
    // may be null (no shadows). Parallel over samples. With `stages`, also adds what the
    // call did to it (timed stages and counts; slower by the clock reads).
    std::vector<LightArrival> arrivals(const PlacedSamples& samples, const RayScene* scene, float offset,
                                       ShadowFieldStages* stages = nullptr) const;

    // The sphere light the specular layer uses for this light.
    const AnalyticLight& highlight() const { return highlight_; }
    // The emitter's radiance along a camera ray (world origin o, unit direction d; the
    // baked views, emitter_views.h), 0 when the ray misses its bounding sphere or the field
    // has no views; `t` is set to the distance along d to the ray's point nearest the centre.
    Imath::V3f emitted(const Imath::V3d& o, const Imath::V3d& d, double& t) const;

    Imath::V3d centre() const { return centre_; }   // world
    double emitterRadius() const { return radius_; }  // world

private:
    struct Texels;
    struct LitBlock;
    struct Scratch;
    std::size_t interpolateMaps(const FieldStencil& stencil, Scratch& scratch) const;
    LightArrival arrivalInField(const Imath::V3d& x, const Imath::V3d& n, const RayScene* scene, float offset,
                                Scratch& scratch, ShadowFieldStages* stages) const;
    struct FarRays;
    LightArrival arrivalBeyond(const Imath::V3d& x, const Imath::V3d& n, const RayScene* scene, float offset,
                               FarRays& rays, std::size_t sample) const;
    void traceFarRays(const RayScene* scene, FarRays& rays, std::vector<LightArrival>& result,
                      ShadowFieldStages* stages) const;
    bool facesAway(const Imath::V3d& x, const Imath::V3d& n) const;  // world; the emitter wholly behind n
    Imath::V3d toLight(const Imath::V3d& world) const;  // a world point in the light's frame (mm)
    double shadowReach(const Imath::V3d& pointLight, const Imath::V3d& directionLight) const;

    std::shared_ptr<const LoadedShadowField> field_;
    Imath::M44d lightToWorld_, worldToLight_;
    Imath::M33d rotation_;  // light to world, scale removed
    double scale_ = 1.0;    // world units per light-frame mm
    Imath::V3d emission_;   // color * intensity * 2^exposure * flicker
    Imath::V3d centre_;     // world
    double radius_ = 0.0;   // world
    AnalyticLight highlight_;
};

}  // namespace opal
