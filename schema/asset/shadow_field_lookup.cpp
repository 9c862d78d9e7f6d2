#include "schema/asset/shadow_field_lookup.h"

#include "schema/error.h"
#include "schema/wavelet/haar.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <string>

namespace opal {
namespace {

// The grid cell of face coordinate c in [-1, 1] on a grid of `size` sample centres: the
// lower sample, in [-1, size - 1] (-1 and size stand for the neighbouring face's samples
// beyond the edge), and the fraction toward the next.
std::pair<std::int32_t, double> gridCell(double c, std::uint32_t size) {
    const double x = std::clamp((c + 1.0) * 0.5 * size - 0.5, -0.5, size - 0.5);
    const auto i = std::int32_t(std::floor(x));
    return {std::min(i, std::int32_t(size) - 1), x - std::min(i, std::int32_t(size) - 1)};
}

}  // namespace

ShadowFieldLookup::ShadowFieldLookup(const ShadowField& field)
    : field_(field), mapLayout_(field.mapFaceSize), cosine_(mapLayout_) {
    texelSolidAngles_.resize(mapLayout_.texels());
    for (std::uint32_t i = 0; i < mapLayout_.texels(); ++i) texelSolidAngles_[i] = mapLayout_.solidAngle(i);
}

// The sample of grid position (u, v) on `face`; a position one step beyond an edge is the
// sample of the neighbouring face nearest to where the grid continues.
std::uint32_t ShadowFieldLookup::directionSample(std::uint32_t face, std::int32_t u, std::int32_t v) const {
    const CubeMapLayout grid(field_.directionFaceSize);
    const auto size = std::int32_t(grid.faceSize());
    if (u >= 0 && v >= 0 && u < size && v < size) return grid.index({face, std::uint32_t(u), std::uint32_t(v)});
    const auto coordinate = [&](std::int32_t i) { return 2.0f * (float(i) + 0.5f) / float(size) - 1.0f; };
    return grid.lookup(CubeMapLayout::faceDirection(face, coordinate(u), coordinate(v)));
}

void ShadowFieldLookup::addDirectionWeights(std::uint32_t shell, const Imath::V3d& direction, double weight,
                                            FieldStencil& stencil) const {
    const CubeFacePoint fp = CubeMapLayout::facePoint(Imath::V3f(direction));
    const auto [u, fu] = gridCell(fp.s, field_.directionFaceSize);
    const auto [v, fv] = gridCell(fp.t, field_.directionFaceSize);
    const std::uint64_t base = std::uint64_t(shell) * field_.directionsPerShell();
    const double weights[4] = {(1 - fu) * (1 - fv), fu * (1 - fv), (1 - fu) * fv, fu * fv};
    for (int corner = 0; corner < 4; ++corner) {
        if (!(weights[corner] > 0.0)) continue;
        const std::uint32_t sample = directionSample(fp.face, u + (corner & 1), v + (corner >> 1));
        stencil.maps[stencil.count++] = {base + sample, weight * weights[corner]};
    }
}

FieldStencil ShadowFieldLookup::stencil(const Imath::V3d& point) const {
    FieldStencil s;
    const Imath::V3d offset = point - field_.centre;
    s.radius = offset.length();
    if (!std::isfinite(s.radius)) throw Error("shadow field lookup: the point is not finite");
    s.direction = s.radius > 0.0 ? offset / s.radius : Imath::V3d(0.0, 1.0, 0.0);
    const std::vector<double>& r = field_.radii;
    if (s.radius > r.back()) {
        s.region = FieldRegion::Beyond;
        addDirectionWeights(field_.shells() - 1, s.direction, 1.0, s);
        return s;
    }
    if (s.radius <= r.front()) {
        s.region = s.radius < r.front() ? FieldRegion::Inside : FieldRegion::Field;
        addDirectionWeights(0, s.direction, 1.0, s);
        return s;
    }
    // r_j < radius <= r_{j+1}; weights linear in 1/r^2.
    const auto j = std::uint32_t(std::lower_bound(r.begin(), r.end(), s.radius) - r.begin()) - 1;
    const double a = 1.0 / (r[j] * r[j]), b = 1.0 / (r[j + 1] * r[j + 1]), x = 1.0 / (s.radius * s.radius);
    const double t = std::clamp((a - x) / (a - b), 0.0, 1.0);
    if (t < 1.0) addDirectionWeights(j, s.direction, 1.0 - t, s);
    if (t > 0.0) addDirectionWeights(j + 1, s.direction, t, s);
    return s;
}

// The blended maps' texels at face size `size`, RGB interleaved, before the clamp.
std::vector<float> ShadowFieldLookup::blendCoefficients(std::span<const MapWeight> maps, std::uint32_t size) const {
    // In the Mallat layout a face's coefficients of the coarser levels fill its top-left
    // size x size corner, and their inverse transform there is the face averaged over
    // blocks of (n / size)^2 texels, times n / size (orthonormal Haar).
    const std::uint32_t n = mapLayout_.faceSize(), fine = n * n, coarse = size * size;
    std::vector<float> coefficients(3 * 6 * std::size_t(coarse), 0.0f);
    std::array<bool, 6> lit{};  // faces with a kept coefficient; the others stay 0
    for (const MapWeight& m : maps) {
        for (std::uint64_t k = field_.offsets[m.map]; k < field_.offsets[m.map + 1]; ++k) {
            const std::uint32_t face = field_.indices[k] / fine, within = field_.indices[k] % fine;
            const std::uint32_t u = within % n, v = within / n;
            if (u >= size || v >= size) continue;
            lit[face] = true;
            const std::size_t at = 3 * (std::size_t(face) * coarse + v * size + u);
            for (int c = 0; c < 3; ++c) coefficients[at + c] += float(m.weight * field_.values[3 * k + c]);
        }
    }
    // The inverse transform of a face of zeros is zeros: only the lit faces are synthesized
    // (a compact emitter lights 1 to 3 faces of each map).
    for (std::uint32_t face = 0; face < 6; ++face)
        if (lit[face])
            haarInverse2D<float>(std::span(coefficients).subspan(std::size_t(face) * coarse * 3, coarse * 3), size, 3);
    const float scale = float(size) / float(n);
    for (float& c : coefficients) c *= scale;
    return coefficients;
}

std::vector<Imath::V3f> ShadowFieldLookup::blend(std::span<const MapWeight> maps, std::uint32_t size) const {
    const std::vector<float> texels = blendCoefficients(maps, size);
    // Radiance is never negative: what the truncated Haar series rings below 0 is 0.
    std::vector<Imath::V3f> radiance(texels.size() / 3);
    for (std::size_t i = 0; i < radiance.size(); ++i)
        radiance[i] = {std::max(0.0f, texels[3 * i]), std::max(0.0f, texels[3 * i + 1]), std::max(0.0f, texels[3 * i + 2])};
    return radiance;
}

std::vector<Imath::V3f> ShadowFieldLookup::mapTerms(std::uint64_t index, std::uint32_t faceSize) const {
    requireFaceSize(faceSize);
    const MapWeight one{index, 1.0};
    const std::vector<float> texels = blendCoefficients({&one, 1}, faceSize);
    std::vector<Imath::V3f> terms(texels.size() / 3);
    for (std::size_t i = 0; i < terms.size(); ++i) terms[i] = {texels[3 * i], texels[3 * i + 1], texels[3 * i + 2]};
    return terms;
}

std::vector<Imath::V3f> ShadowFieldLookup::map(std::uint64_t index) const {
    const MapWeight one{index, 1.0};
    return blend({&one, 1}, mapLayout_.faceSize());
}

Imath::V3d ShadowFieldLookup::integrate(const std::vector<Imath::V3f>& radiance, const Imath::V3d* normal) const {
    Imath::V3d sum(0.0);
    for (std::size_t i = 0; i < radiance.size(); ++i) {
        const double weight = normal ? cosine_.weight(std::uint32_t(i), *normal) : texelSolidAngles_[i];
        if (weight > 0.0) sum += Imath::V3d(radiance[i]) * weight;
    }
    return sum;
}

Imath::V3d ShadowFieldLookup::farIntensity(const Imath::V3d& direction) const {
    FieldStencil s;
    addDirectionWeights(field_.shells() - 1, direction, 1.0, s);
    const double outer = field_.radii.back();
    return integrate(blend({s.maps.data(), s.count}, mapLayout_.faceSize()), nullptr) * (outer * outer);
}

std::vector<Imath::V3f> ShadowFieldLookup::incidentRadiance(const Imath::V3d& point) const {
    return incidentRadiance(point, mapLayout_.faceSize());
}

void ShadowFieldLookup::requireFaceSize(std::uint32_t faceSize) const {
    if (faceSize == 0 || (faceSize & (faceSize - 1)) != 0 || faceSize > mapLayout_.faceSize())
        throw Error("shadow field lookup: face size " + std::to_string(faceSize) +
                    " is not a power of two up to the maps' " + std::to_string(mapLayout_.faceSize()));
}

std::vector<Imath::V3f> ShadowFieldLookup::incidentRadiance(const Imath::V3d& point, std::uint32_t faceSize) const {
    requireFaceSize(faceSize);
    const FieldStencil s = stencil(point);
    if (s.region != FieldRegion::Beyond) return blend({s.maps.data(), s.count}, faceSize);
    const Imath::V3d irradiance = farIntensity(s.direction) / (s.radius * s.radius);
    const CubeMapLayout layout(faceSize);
    std::vector<Imath::V3f> radiance(layout.texels(), Imath::V3f(0.0f));
    const std::uint32_t texel = layout.lookup(Imath::V3f(-s.direction));
    radiance[texel] = Imath::V3f(irradiance / layout.solidAngle(texel));
    return radiance;
}

Imath::V3d ShadowFieldLookup::irradiance(const Imath::V3d& point, const Imath::V3d& normal) const {
    const FieldStencil s = stencil(point);
    if (s.region != FieldRegion::Beyond) return integrate(blend({s.maps.data(), s.count}, mapLayout_.faceSize()), &normal);
    const double cosine = std::max(0.0, -normal.dot(s.direction));
    if (cosine == 0.0) return Imath::V3d(0.0);
    return farIntensity(s.direction) * (cosine / (s.radius * s.radius));
}

}  // namespace opal
