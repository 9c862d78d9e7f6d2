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
#include <chrono>
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

// Adds the time since the last lap to a stage, when timing (stages non-null).
class StageClock {
public:
    explicit StageClock(const ShadowFieldStages* stages) : on_(stages != nullptr) {
        if (on_) last_ = std::chrono::steady_clock::now();
    }
    void lap(double& stageMs) {
        if (!on_) return;
        const auto now = std::chrono::steady_clock::now();
        stageMs += std::chrono::duration<double, std::milli>(now - last_).count();
        last_ = now;
    }

private:
    bool on_;
    std::chrono::steady_clock::time_point last_;
};

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
    const CubeMapLayout grid(field.directionFaceSize);
    farIntensities.resize(field.directionsPerShell());
    tbb::parallel_for(std::uint32_t(0), field.directionsPerShell(), [&](std::uint32_t d) {
        farIntensities[d] = lookup.farIntensity(Imath::V3d(grid.direction(d)).normalized());
    });
    const std::uint32_t side = std::max<std::uint32_t>(1, layout.faceSize() / kBlockSide);
    blocks = 6 * side * side;
    for (std::uint32_t k = 0; k < layout.texels(); ++k) {
        const CubeMapTexel t = layout.texel(k);
        texels.push_back({layout.direction(k), (t.face * side + t.v / kBlockSide) * side + t.u / kBlockSide});
    }
}

Imath::V3d LoadedShadowField::farIntensity(const FieldStencil& beyond) const {
    const std::uint64_t outerShell = std::uint64_t(field.shells() - 1) * field.directionsPerShell();
    Imath::V3d intensity(0.0);
    for (std::uint32_t i = 0; i < beyond.count; ++i)
        intensity += farIntensities[beyond.maps[i].map - outerShell] * beyond.maps[i].weight;
    return intensity;
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

namespace {
constexpr std::size_t kNoRay = std::numeric_limits<std::size_t>::max();
constexpr double kFaintBlock = 0.02;

// The energy below which a sample's lit blocks are faint: the faintest blocks, taken in
// ascending order while their sum stays under kFaintBlock of the sample's light. So the
// untraced light is bounded by that fraction, and the brightest block is always traced.
// Reorders `energies`.
double faintEnergy(std::span<double> energies) {
    std::sort(energies.begin(), energies.end());
    double all = 0.0;
    for (double e : energies) all += e;
    double sum = 0.0;
    for (double e : energies) {
        if (sum + e >= kFaintBlock * all) return e;
        sum += e;
    }
    return 0.0;  // no light
}
}  // namespace

struct ShadowFieldLight::LitBlock {
    Imath::V3d e{0.0};
    Imath::V3d direction{0.0};
    std::size_t ray = kNoRay;  // its occlusion ray, or kNoRay (no scene, faint, or the sample inside the sphere)
    bool faint = false;
};

// A chunk's far-field occlusion rays and the samples they belong to.
struct ShadowFieldLight::FarRays {
    std::vector<Ray> rays;
    std::vector<std::size_t> samples;
    std::vector<std::uint8_t> blocked;
};

// A worker's buffers for arrivalInField, all zero between samples. Touched texels and
// blocks are listed without a branch (the index is always written, the count advances
// only for a first touch): the seen-test mispredicts on most of a sample's ~1,200 terms.
struct ShadowFieldLight::Scratch {
    std::vector<Float4> radiance;  // per texel of the decode layout (RGB, 0)
    std::vector<std::uint8_t> seen, blockSeen;
    // The first `count` entries are live; one spare slot takes the write after the last.
    std::vector<std::uint32_t> touched, touchedBlocks;
    std::vector<Texels> blocks;
    // Per sample: its lit blocks (irradiance, unit direction, ray or kNoRay) and their rays.
    std::vector<LitBlock> lit;
    std::vector<double> energies;  // the lit blocks' light, for faintEnergy
    std::vector<Ray> rays;
    std::vector<std::uint8_t> blocked;
    FarRays far;

    explicit Scratch(const LoadedShadowField& f)
        : radiance(f.layout.texels(), Float4{}),
          seen(f.layout.texels(), 0),
          blockSeen(f.blocks, 0),
          touched(f.layout.texels() + 1),
          touchedBlocks(f.blocks + 1),
          blocks(f.blocks),
          lit(f.blocks),
          energies(f.blocks),
          rays(f.blocks),
          blocked(f.blocks) {}
};

// Sums the stencil's weighted sparse maps into s.radiance: the interpolated field,
// incidentRadiance's value up to rounding. Returns how many texels it touched.
std::size_t ShadowFieldLight::interpolateMaps(const FieldStencil& stencil, Scratch& s) const {
    // Raw pointers: a byte store may alias a vector's own pointer, which the compiler
    // would otherwise reload on every term.
    std::uint32_t* const touched = s.touched.data();
    std::uint8_t* const seen = s.seen.data();
    Float4* const radiance = s.radiance.data();
    std::size_t count = 0;
    for (std::uint32_t i = 0; i < stencil.count; ++i) {
        const float w = float(stencil.maps[i].weight);
        const Float4 weight = {w, w, w, w};
        const std::span<const std::uint32_t> texels = field_->maps.texels(stencil.maps[i].map);
        const Float4* const terms = field_->maps.terms(stencil.maps[i].map).data();
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
                                              float offset, Scratch& s, ShadowFieldStages* stages) const {
    ShadowFieldStages ignored;
    ShadowFieldStages& st = stages ? *stages : ignored;
    StageClock clock(stages);
    const Imath::V3d p = toLight(x), nl = n * rotation_.transposed();
    const FieldStencil stencil = field_->lookup.stencil(p);
    clock.lap(st.setupMs);
    const std::size_t touched = interpolateMaps(stencil, s);
    clock.lap(st.interpolationMs);
    st.texels += touched;
    for (std::uint32_t i = 0; stages && i < stencil.count; ++i) st.terms += field_->maps.texels(stencil.maps[i].map).size();
    std::size_t litBlocks = 0;
    for (std::size_t t = 0; t < touched; ++t) {
        const std::uint32_t k = s.touched[t];
        // Radiance is never negative: what the truncated Haar series rings below 0 is 0.
        const Float4 r = std::exchange(s.radiance[k], Float4{});
        const Imath::V3f l(std::max(0.0f, r[0]), std::max(0.0f, r[1]), std::max(0.0f, r[2]));
        s.seen[k] = 0;
        if (l.x + l.y + l.z <= 0.0f) continue;
        const double w = field_->cosine.weight(k, nl);
        if (w <= 0.0) continue;
        const LoadedShadowField::Texel& texel = field_->texels[k];
        const std::uint32_t b = texel.block;
        s.touchedBlocks[litBlocks] = b;
        litBlocks += 1u - s.blockSeen[b];
        s.blockSeen[b] = 1;
        const Imath::V3d e = Imath::V3d(l) * w;
        s.blocks[b].e += e;
        s.blocks[b].direction += Imath::V3d(texel.direction) * channelSum(e);
    }
    clock.lap(st.cosineMs);
    // The lit blocks in order, and one occlusion ray each: rays from one origin toward one
    // emitter, traced together as coherent packets. The faint blocks cast none: they take
    // the visible fraction of the traced blocks' light.
    for (std::size_t t = 0; t < litBlocks; ++t) s.energies[t] = channelSum(s.blocks[s.touchedBlocks[t]].e);
    const double faintBelow = faintEnergy({s.energies.data(), litBlocks});
    std::size_t lit = 0, rays = 0;
    const Imath::V3f origin = Imath::V3f(x + n * double(offset));
    for (std::size_t t = 0; t < litBlocks; ++t) {
        const std::uint32_t b = s.touchedBlocks[t];
        s.blockSeen[b] = 0;
        const Texels block = std::exchange(s.blocks[b], Texels{});
        if (channelSum(block.e) <= 0.0) continue;
        const Imath::V3d d = block.direction.normalized();
        const bool faint = channelSum(block.e) < faintBelow;
        const double reach = scene && !faint ? shadowReach(p, d) * scale_ * (1.0 - 1e-4) : 0.0;
        s.lit[lit] = {block.e, d, reach > 0.0 ? rays : kNoRay, faint};
        if (reach > 0.0) s.rays[rays++] = Ray(origin, Imath::V3f(d * rotation_), 0.0f, float(reach));
        ++lit;
    }
    if (rays) scene->occludedCoherent({s.rays.data(), rays}, {s.blocked.data(), rays});
    st.rays += rays;
    Imath::V3d total(0.0), faintTotal(0.0);
    double cosineSum = 0.0, faintCosineSum = 0.0, traced = 0.0, tracedVisible = 0.0;
    for (std::size_t t = 0; t < lit; ++t) {
        const LitBlock& block = s.lit[t];
        const double e = channelSum(block.e), cosine = e * std::max(0.0, block.direction.dot(nl));
        if (block.faint) {
            faintTotal += block.e;
            faintCosineSum += cosine;
            continue;
        }
        traced += e;
        if (block.ray != kNoRay && s.blocked[block.ray]) {
            ++st.blocked;
            continue;
        }
        tracedVisible += e;
        total += block.e;
        cosineSum += cosine;
    }
    const double visible = traced > 0.0 ? tracedVisible / traced : 1.0;
    total += faintTotal * visible;
    cosineSum += faintCosineSum * visible;
    clock.lap(st.visibilityMs);
    const double sum = channelSum(total);
    if (!(sum > 0.0)) return {};
    const double mu = std::clamp(cosineSum / sum, 1e-3, 1.0);
    const Imath::V3d perp = total * emission_ / mu;
    return {float(mu), Imath::V3f(perp)};
}

// Exact, not an estimate: every point of the emitter's bounding sphere lies behind the
// sample's tangent plane, so no light arrives with a positive cosine. What the truncated
// Haar maps would smear onto such a sample is their ringing, not light.
bool ShadowFieldLight::facesAway(const Imath::V3d& x, const Imath::V3d& n) const {
    return n.dot(centre_ - x) < -radius_;
}

// Beyond the outer sphere: the far-field point light, E_perp = I(w) / r^2. Its occlusion ray
// (toward the emitter's centre, to its bounding sphere) is queued in `rays` for sample
// `sample`: a chunk's samples trace theirs together, as packets of nearly parallel rays.
LightArrival ShadowFieldLight::arrivalBeyond(const Imath::V3d& x, const Imath::V3d& n, const RayScene* scene,
                                             float offset, FarRays& rays, std::size_t sample) const {
    const Imath::V3d p = toLight(x);
    const FieldStencil stencil = field_->lookup.stencil(p);
    const Imath::V3d w = stencil.direction;  // from the centre toward the sample
    const double r = stencil.radius;
    const double mu = (n * rotation_.transposed()).dot(-w);
    if (mu <= 0.0) return {};
    if (scene) {
        const double reach = shadowReach(p, -w) * scale_ * (1.0 - 1e-4);
        if (reach > 0.0) {
            rays.rays.push_back(Ray(Imath::V3f(x + n * double(offset)), Imath::V3f(-w * rotation_), 0.0f, float(reach)));
            rays.samples.push_back(sample);
        }
    }
    Imath::V3d perp = field_->farIntensity(stencil) * emission_ / (r * r);
    for (int c = 0; c < 3; ++c) perp[c] = std::min(perp[c], kMaxSampleIrradiance);
    return {float(mu), Imath::V3f(perp)};
}

void ShadowFieldLight::traceFarRays(const RayScene* scene, FarRays& far, std::vector<LightArrival>& result,
                                    ShadowFieldStages* stages) const {
    const std::size_t n = far.rays.size();
    if (n == 0) return;
    far.blocked.resize(n);
    scene->occludedCoherent(far.rays, far.blocked);
    for (std::size_t j = 0; j < n; ++j)
        if (far.blocked[j]) result[far.samples[j]] = {};
    if (stages) {
        stages->rays += n;
        for (std::uint8_t b : far.blocked) stages->blocked += b;
    }
    far.rays.clear();
    far.samples.clear();
}

std::vector<LightArrival> ShadowFieldLight::arrivals(const PlacedSamples& samples, const RayScene* scene,
                                                     float offset, ShadowFieldStages* stages) const {
    const std::size_t n = samples.positions.size();
    std::vector<LightArrival> result(n);
    const double outer = field_->field.radii.back();
    tbb::enumerable_thread_specific<Scratch> scratch([&] { return Scratch(*field_); });
    tbb::enumerable_thread_specific<ShadowFieldStages> counted;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 64), [&](const tbb::blocked_range<std::size_t>& range) {
        Scratch& s = scratch.local();
        ShadowFieldStages* st = stages ? &counted.local() : nullptr;
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
            StageClock clock(st);
            const Imath::V3d x(samples.positions[i]), normal(samples.normals[i]);
            if (facesAway(x, normal)) {
                if (st) ++st->samples, ++st->facingAway;
                continue;  // result[i] stays {}
            }
            const bool beyond = (toLight(x) - field_->field.centre).length() > outer;
            if (st) {
                ++st->samples;
                st->beyond += beyond;
                clock.lap(st->setupMs);
            }
            if (!beyond) {
                result[i] = arrivalInField(x, normal, scene, offset, s, st);
                continue;
            }
            result[i] = arrivalBeyond(x, normal, scene, offset, s.far, i);
            if (st) clock.lap(st->farFieldMs);
        }
        StageClock clock(st);
        traceFarRays(scene, s.far, result, st);
        if (st) clock.lap(st->farFieldMs);
    });
    if (stages)
        for (const ShadowFieldStages& st : counted) *stages += st;
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
