#include "bake/light/incident_radiance.h"

#include "schema/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace opal {
namespace {

float angleBetween(const Imath::V3f& a, const Imath::V3f& b) { return std::acos(std::clamp(a.dot(b), -1.0f, 1.0f)); }

}  // namespace

IncidentRadianceRenderer::IncidentRadianceRenderer(const EmitterScene& scene, std::uint32_t mapFaceSize,
                                                   std::uint32_t raysPerSide)
    : scene_(scene), layout_(mapFaceSize), raysPerSide_(raysPerSide) {
    if (raysPerSide == 0 || raysPerSide > 64) throw Error("rays per texel side must be 1 to 64");
    const float size = float(mapFaceSize);
    for (std::uint32_t i = 0; i < layout_.texels(); ++i) {
        const CubeMapTexel t = layout_.texel(i);
        const Imath::V3f centre = layout_.direction(i);
        float half = 0.0f;
        for (int corner = 0; corner < 4; ++corner) {
            const float s = 2.0f * float(t.u + (corner & 1)) / size - 1.0f;
            const float v = 2.0f * float(t.v + (corner >> 1)) / size - 1.0f;
            half = std::max(half, angleBetween(centre, CubeMapLayout::faceDirection(t.face, s, v)));
        }
        centres_.push_back(centre);
        halfAngles_.push_back(half);
    }
}

std::vector<std::uint32_t> IncidentRadianceRenderer::candidateTexels(const Imath::V3f& point) const {
    const Imath::V3f toCentre = Imath::V3f(scene_.bounds().centre) - point;
    const float distance = toCentre.length();
    const float radius = float(scene_.bounds().radius);
    std::vector<std::uint32_t> texels;
    if (!(distance > radius)) {  // inside the bounding sphere: every direction may see it
        for (std::uint32_t i = 0; i < layout_.texels(); ++i) texels.push_back(i);
        return texels;
    }
    const Imath::V3f axis = toCentre / distance;
    const float emitterCone = std::asin(radius / distance) + 1e-4f;  // a margin for rounding
    for (std::uint32_t i = 0; i < layout_.texels(); ++i) {
        const float reach = emitterCone + halfAngles_[i];
        if (reach >= std::numbers::pi_v<float> || centres_[i].dot(axis) >= std::cos(reach)) texels.push_back(i);
    }
    return texels;
}

void IncidentRadianceRenderer::addRays(const Imath::V3f& point, std::uint32_t texel, std::uint32_t k, Random& random,
                                       std::vector<Ray>& rays) const {
    const CubeMapTexel t = layout_.texel(texel);
    const float size = float(layout_.faceSize());
    for (std::uint32_t a = 0; a < k; ++a)
        for (std::uint32_t b = 0; b < k; ++b) {
            const float s = 2.0f * (float(t.u) + (float(b) + random.uniformFloat()) / float(k)) / size - 1.0f;
            const float v = 2.0f * (float(t.v) + (float(a) + random.uniformFloat()) / float(k)) / size - 1.0f;
            rays.emplace_back(point, CubeMapLayout::faceDirection(t.face, s, v), 0.0f,
                              std::numeric_limits<float>::infinity());
        }
}

// Traces `rays` (perTexel per texel, in the order of `texels`) and stores each texel's
// mean in `rgb` and what its rays saw in `seen` (kMixed, kNothing or the part hit).
void IncidentRadianceRenderer::trace(std::span<const std::uint32_t> texels, std::span<const Ray> rays,
                                     std::uint32_t perTexel, std::vector<float>& rgb,
                                     std::vector<std::int64_t>& seen) const {
    std::vector<std::optional<RayHit>> hits(rays.size());
    scene_.rays().intersectCoherent(rays, hits);
    const auto what = [](const std::optional<RayHit>& hit) { return hit ? std::int64_t(hit->prim) : kNothing; };
    for (std::size_t n = 0; n < texels.size(); ++n) {
        Imath::V3f sum(0.0f);
        const std::size_t first = n * perTexel;
        std::int64_t saw = what(hits[first]);
        for (std::size_t ray = first; ray < first + perTexel; ++ray) {
            sum += scene_.radiance(rays[ray], hits[ray]);
            if (what(hits[ray]) != saw) saw = kMixed;
        }
        sum /= float(perTexel);
        for (int c = 0; c < 3; ++c) rgb[3 * std::size_t(texels[n]) + c] = sum[c];
        seen[texels[n]] = saw;
    }
}

// A texel may hold an edge it did not see: its rays disagreed, a neighbour on its face
// saw something else, or it lies on its face's border (its neighbours there are on
// another face).
bool IncidentRadianceRenderer::mayHoldEdge(std::uint32_t texel, const std::vector<std::int64_t>& seen) const {
    if (seen[texel] == kMixed) return true;
    const CubeMapTexel t = layout_.texel(texel);
    const std::uint32_t last = layout_.faceSize() - 1;
    if (t.u == 0 || t.v == 0 || t.u == last || t.v == last) return true;
    for (const CubeMapTexel n : {CubeMapTexel{t.face, t.u - 1, t.v}, CubeMapTexel{t.face, t.u + 1, t.v},
                                 CubeMapTexel{t.face, t.u, t.v - 1}, CubeMapTexel{t.face, t.u, t.v + 1}})
        if (seen[layout_.index(n)] != seen[texel]) return true;
    return false;
}

std::vector<float> IncidentRadianceRenderer::render(const Imath::V3f& point, Random& random,
                                                    std::uint64_t* rayCount) const {
    std::vector<float> rgb(3 * std::size_t(layout_.texels()), 0.0f);
    std::vector<std::int64_t> seen(layout_.texels(), kNothing);  // texels outside the cone see nothing
    const std::vector<std::uint32_t> texels = candidateTexels(point);
    const std::uint32_t k = raysPerSide_, first = std::min(k, kFirstPassSide);
    std::vector<Ray> rays;
    rays.reserve(texels.size() * first * first);
    for (std::uint32_t i : texels) addRays(point, i, first, random, rays);
    trace(texels, rays, first * first, rgb, seen);
    std::uint64_t traced = rays.size();
    if (k > first) {
        std::vector<std::uint32_t> edges;
        for (std::uint32_t i : texels)
            if (mayHoldEdge(i, seen)) edges.push_back(i);
        rays.clear();
        for (std::uint32_t i : edges) addRays(point, i, k, random, rays);
        std::vector<std::int64_t> refined(seen);
        trace(edges, rays, k * k, rgb, refined);
        traced += rays.size();
    }
    if (rayCount) *rayCount += traced;
    return rgb;
}

}  // namespace opal
