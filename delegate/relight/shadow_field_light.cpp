#include "delegate/relight/shadow_field_light.h"

#include "delegate/relight/light_emission.h"
#include "delegate/relight/light_flicker.h"
#include "raytrace/ray_scene.h"
#include "schema/error.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <Imath/ImathMatrixAlgo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace opal {

namespace {

constexpr double kPi = std::numbers::pi;
// How much coarser than the maps irradiance is formed, and the texels per side of a
// visibility block in that layout (4 x 4 map texels: one occlusion ray per lit block).
constexpr std::uint32_t kDecodeDivisor = 2;
constexpr std::uint32_t kBlockSide = 2;

double channelSum(const Imath::V3d& v) { return v.x + v.y + v.z; }

// The sphere light with the emitter's bounding radius whose intensity, seen from outside,
// is the field's mean far-field intensity times the light's emission (analytic_light.h:
// I = L_e pi r^2).
AnalyticLight highlightOf(const LoadedShadowField& field, const Imath::V3d& emission, const Imath::V3d& centre,
                          double radius) {
    hd::LightDesc desc;
    desc.kind = hd::LightKind::Sphere;
    desc.transform.setTranslation(centre);
    desc.radius = radius;
    const Imath::V3d intensity = field.meanIntensity * emission;
    const double area = kPi * radius * radius;
    desc.color = Rgb(intensity.x / area, intensity.y / area, intensity.z / area);
    desc.intensity = 1.0;
    return AnalyticLight::fromDesc(desc);
}

Imath::V3d emissionOf(const hd::LightDesc& desc) {
    const Rgb le = emittedRadiance(desc);
    return {le.x, le.y, le.z};
}

}  // namespace

LoadedShadowField::LoadedShadowField(ShadowField f)
    : field(std::move(f)),
      lookup(field),
      layout(std::max<std::uint32_t>(1, field.mapFaceSize / kDecodeDivisor)),
      cosine(layout),
      maps(lookup, layout.faceSize()) {
    // The mean of I(w) over directions, from the outer shell's 24 coarsest directions
    // (enough for a highlight's strength: the far field is smooth by construction).
    const CubeMapLayout directions(2);
    for (std::uint32_t i = 0; i < directions.texels(); ++i)
        meanIntensity += lookup.farIntensity(Imath::V3d(directions.direction(i))) *
                         (directions.solidAngle(i) / (4.0 * kPi));
    const std::uint32_t side = std::max<std::uint32_t>(1, layout.faceSize() / kBlockSide);
    blocks = 6 * side * side;
    for (std::uint32_t k = 0; k < layout.texels(); ++k) {
        const CubeMapTexel t = layout.texel(k);
        texelDirections.push_back(layout.direction(k));
        texelBlocks.push_back((t.face * side + t.v / kBlockSide) * side + t.u / kBlockSide);
    }
}

ShadowFieldLight::ShadowFieldLight(std::shared_ptr<const LoadedShadowField> field, const hd::LightDesc& desc)
    : field_(std::move(field)) {
    if (!field_) throw Error("shadow-field light: no field");
    if (desc.kind != hd::LightKind::ShadowField) throw Error("shadow-field light: the description is another kind");
    rotation_ = rotationOf(desc.transform, "shadow-field light");
    scale_ = Imath::V3d(desc.transform[0][0], desc.transform[0][1], desc.transform[0][2]).length();
    const ShadowField& f = field_->field;
    const FlickerState flicker = lightFlicker(desc.flicker, desc.time);
    Imath::M44d jitter;  // the flicker's sway, in the light's frame (row vectors: applied first)
    jitter.setTranslation(flicker.offset * f.emitterRadius);
    lightToWorld_ = jitter * desc.transform;
    worldToLight_ = lightToWorld_.inverse();
    emission_ = emissionOf(desc) * flicker.intensity;
    lightToWorld_.multVecMatrix(f.centre, centre_);
    radius_ = f.emitterRadius * scale_;
    highlight_ = highlightOf(*field_, emission_, centre_, radius_);
}

Imath::V3d ShadowFieldLight::toLight(const Imath::V3d& world) const {
    Imath::V3d p;
    worldToLight_.multVecMatrix(world, p);
    return p;
}

// Light-frame distance from p along unit d to where the ray enters the emitter's bounding
// sphere (to its point nearest the centre when it passes beside it; 0 inside it).
double ShadowFieldLight::shadowReach(const Imath::V3d& p, const Imath::V3d& d) const {
    const ShadowField& f = field_->field;
    const Imath::V3d oc = p - f.centre;
    const double b = oc.dot(d), c = oc.length2() - f.emitterRadius * f.emitterRadius;
    if (c <= 0.0) return 0.0;
    const double disc = b * b - c;
    if (disc >= 0.0 && -b - std::sqrt(disc) > 0.0) return -b - std::sqrt(disc);
    return std::max(0.0, -b);
}

// One lit block of texels: its irradiance and the irradiance-weighted sum of directions.
struct ShadowFieldLight::Texels {
    Imath::V3d e{0.0};
    Imath::V3d direction{0.0};
};

// A worker's buffers for arrivalInField, all zero between samples. Touched texels and
// blocks are listed without a branch (the index is always written, the count advances
// only for a first touch): the seen-test mispredicts on most of a sample's ~1,200 terms.
struct ShadowFieldLight::Scratch {
    std::vector<Imath::V3f> radiance;  // per texel of the decode layout
    std::vector<std::uint8_t> seen, blockSeen;
    // The first `count` entries are live; one spare slot takes the write after the last.
    std::vector<std::uint32_t> touched, touchedBlocks;
    std::vector<Texels> blocks;

    explicit Scratch(const LoadedShadowField& f)
        : radiance(f.layout.texels(), Imath::V3f(0.0f)),
          seen(f.layout.texels(), 0),
          blockSeen(f.blocks, 0),
          touched(f.layout.texels() + 1),
          touchedBlocks(f.blocks + 1),
          blocks(f.blocks) {}
};

// Sums the stencil's weighted sparse maps into s.radiance: the interpolated field,
// incidentRadiance's value up to rounding. Returns how many texels it touched.
std::size_t ShadowFieldLight::interpolateMaps(const FieldStencil& stencil, Scratch& s) const {
    // Raw pointers: a byte store may alias a vector's own pointer, which the compiler
    // would otherwise reload on every term.
    std::uint32_t* const touched = s.touched.data();
    std::uint8_t* const seen = s.seen.data();
    Imath::V3f* const radiance = s.radiance.data();
    std::size_t count = 0;
    for (std::uint32_t i = 0; i < stencil.count; ++i) {
        const float weight = float(stencil.maps[i].weight);
        const std::span<const std::uint32_t> texels = field_->maps.texels(stencil.maps[i].map);
        const std::span<const Imath::V3f> terms = field_->maps.terms(stencil.maps[i].map);
        for (std::size_t j = 0; j < texels.size(); ++j) {
            const std::uint32_t k = texels[j];
            touched[count] = k;
            count += 1u - seen[k];
            seen[k] = 1;
            radiance[k] += terms[j] * weight;
        }
    }
    return count;
}

// The interpolated field, clamped, weighed by each texel's cosine integral and gathered
// into visibility blocks; then one occlusion ray per lit block.
LightArrival ShadowFieldLight::arrivalInField(const Imath::V3d& x, const Imath::V3d& n, const RayScene* scene,
                                              float offset, Scratch& s) const {
    const Imath::V3d p = toLight(x), nl = n * rotation_.transposed();
    const std::size_t touched = interpolateMaps(field_->lookup.stencil(p), s);
    std::size_t litBlocks = 0;
    for (std::size_t t = 0; t < touched; ++t) {
        const std::uint32_t k = s.touched[t];
        // Radiance is never negative: what the truncated Haar series rings below 0 is 0.
        const Imath::V3f l(std::max(0.0f, s.radiance[k].x), std::max(0.0f, s.radiance[k].y),
                           std::max(0.0f, s.radiance[k].z));
        s.radiance[k] = Imath::V3f(0.0f);
        s.seen[k] = 0;
        if (l.x + l.y + l.z <= 0.0f) continue;
        const double w = field_->cosine.weight(k, nl);
        if (w <= 0.0) continue;
        const std::uint32_t b = field_->texelBlocks[k];
        s.touchedBlocks[litBlocks] = b;
        litBlocks += 1u - s.blockSeen[b];
        s.blockSeen[b] = 1;
        const Imath::V3d e = Imath::V3d(l) * w;
        s.blocks[b].e += e;
        s.blocks[b].direction += Imath::V3d(field_->texelDirections[k]) * channelSum(e);
    }
    Imath::V3d total(0.0);
    double cosineSum = 0.0;
    const Imath::V3f origin = Imath::V3f(x + n * double(offset));
    for (std::size_t t = 0; t < litBlocks; ++t) {
        const std::uint32_t b = s.touchedBlocks[t];
        s.blockSeen[b] = 0;
        const Texels lit = std::exchange(s.blocks[b], Texels{});
        if (channelSum(lit.e) <= 0.0) continue;
        const Imath::V3d d = lit.direction.normalized();
        if (scene) {
            const double reach = shadowReach(p, d) * scale_ * (1.0 - 1e-4);
            if (reach > 0.0 && scene->occluded(Ray(origin, Imath::V3f(d * rotation_), 0.0f, float(reach)))) continue;
        }
        total += lit.e;
        cosineSum += channelSum(lit.e) * std::max(0.0, d.dot(nl));
    }
    const double sum = channelSum(total);
    if (!(sum > 0.0)) return {};
    const double mu = std::clamp(cosineSum / sum, 1e-3, 1.0);
    const Imath::V3d perp = total * emission_ / mu;
    return {float(mu), Imath::V3f(perp)};
}

LightArrival ShadowFieldLight::arrivalBeyond(const Imath::V3d& x, const Imath::V3d& n, const RayScene* scene,
                                             float offset) const {
    const ShadowField& f = field_->field;
    const Imath::V3d p = toLight(x);
    const Imath::V3d outward = p - f.centre;
    const double r = outward.length();
    const Imath::V3d w = outward / r;  // from the centre toward the sample
    const double mu = (n * rotation_.transposed()).dot(-w);
    if (mu <= 0.0) return {};
    if (scene) {
        const Imath::V3f origin = Imath::V3f(x + n * double(offset));
        const double reach = shadowReach(p, -w) * scale_ * (1.0 - 1e-4);
        if (reach > 0.0 && scene->occluded(Ray(origin, Imath::V3f(-w * rotation_), 0.0f, float(reach)))) return {};
    }
    Imath::V3d perp = field_->lookup.farIntensity(w) * emission_ / (r * r);
    for (int c = 0; c < 3; ++c) perp[c] = std::min(perp[c], kMaxSampleIrradiance);
    return {float(mu), Imath::V3f(perp)};
}

std::vector<LightArrival> ShadowFieldLight::arrivals(const PlacedSamples& samples, const RayScene* scene,
                                                     float offset) const {
    const std::size_t n = samples.positions.size();
    std::vector<LightArrival> result(n);
    const double outer = field_->field.radii.back();
    tbb::enumerable_thread_specific<Scratch> scratch([&] { return Scratch(*field_); });
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 64), [&](const tbb::blocked_range<std::size_t>& range) {
        Scratch& s = scratch.local();
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
            const Imath::V3d x(samples.positions[i]), normal(samples.normals[i]);
            const bool beyond = (toLight(x) - field_->field.centre).length() > outer;
            result[i] = beyond ? arrivalBeyond(x, normal, scene, offset) : arrivalInField(x, normal, scene, offset, s);
        }
    });
    return result;
}

Imath::V3f ShadowFieldLight::emitted(const Imath::V3d& o, const Imath::V3d& d, double& t) const {
    const ShadowField& f = field_->field;
    const Imath::V3d ol = toLight(o), dl = (d * rotation_.transposed()).normalized();
    const double tl = (f.centre - ol).dot(dl);
    t = tl * scale_;
    if (tl <= 0.0) return Imath::V3f(0.0f);
    return viewedRadiance(f.views, f.emitterRadius, dl, ol + dl * tl - f.centre) * Imath::V3f(emission_);
}

}  // namespace opal
