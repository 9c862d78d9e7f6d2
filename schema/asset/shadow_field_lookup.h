// Evaluating a shadow field (shadow_field.h; formulas in docs/ARCHITECTURE.md#shadow-field)
// at a point of the light's frame (mm):
//   - inside the field (inner radius r_0 <= r <= outer radius r_last): the incident
//     radiance cube map interpolated trilinearly from the 8 surrounding sample points:
//     bilinearly in the face coordinates of the face the point's direction falls on, on
//     that face's grid of sample directions continued one step past each edge (within half
//     a step of an edge, the samples beyond it are the neighbouring face's nearest to
//     where the grid continues),
//     and between the two enclosing shells with weights linear in 1/r^2, so a field that
//     falls off as inverse square is interpolated exactly;
//   - inside the inner sphere (r < r_0): the inner shell at the point's direction (the
//     nearest shell);
//   - beyond the outer sphere (r > r_last): a point light at the centre with the far
//     radius's directional intensity I(w) = r_last^2 * sum_texels L Omega of the outer
//     shell's interpolated map at w; E = I(w) max(0, -n.w) / r^2.
// Interpolation is linear in the maps, so it is done on their Haar coefficients, then one
// inverse transform gives the map; texels the truncated Haar series rings below zero are
// clamped to 0 (radiance is never negative). The lookup keeps a reference to the field.
// Cost at the shipped sizes: about 0.13 ms per full-size irradiance or cube-map query (one blend,
// one inverse Haar transform of 6 x 32 x 32 RGB texels, one cosine-weighted sum).
#pragma once

#include "schema/asset/cube_map.h"
#include "schema/asset/cube_map_cosine.h"
#include "schema/asset/shadow_field.h"

#include <Imath/ImathVec.h>

#include <array>
#include <span>
#include <cstdint>
#include <vector>

namespace opal {

enum class FieldRegion { Inside, Field, Beyond };

struct MapWeight {
    std::uint64_t map = 0;
    double weight = 0.0;
};

// The sample points' maps, and their weights (summing to 1), that make the field at a
// point; for Beyond, those of the outer shell at the point's direction.
struct FieldStencil {
    FieldRegion region = FieldRegion::Field;
    double radius = 0.0;         // |p - centre|, mm
    Imath::V3d direction{0.0};   // (p - centre) / radius; +Y for the centre itself
    std::array<MapWeight, 8> maps{};
    std::uint32_t count = 0;
};

class ShadowFieldLookup {
public:
    explicit ShadowFieldLookup(const ShadowField& field);

    const ShadowField& field() const { return field_; }
    const CubeMapLayout& mapLayout() const { return mapLayout_; }

    FieldStencil stencil(const Imath::V3d& point) const;

    // Incident radiance at `point`: one RGB triple per texel of mapLayout(), in the
    // direction the light arrives from (a texel's direction points toward the emitter).
    // Beyond the outer sphere, the point light: all of E = I(w) / r^2 in the one texel
    // holding -w, as radiance E / Omega_texel.
    std::vector<Imath::V3f> incidentRadiance(const Imath::V3d& point) const;
    // The same averaged to a cube map of face size `faceSize` (a power of two up to the
    // maps'): each texel the mean over the map texels it covers, from the coarse levels'
    // coefficients alone (cheaper by about (mapFaceSize / faceSize)^2). Throws opal::Error
    // for another face size.
    std::vector<Imath::V3f> incidentRadiance(const Imath::V3d& point, std::uint32_t faceSize) const;
    // RGB irradiance on a surface at `point` with unit normal `normal`: the sum over
    // texels of L times the integral of max(0, n.w) over the texel (cube_map_cosine.h),
    // or the point light beyond the field.
    Imath::V3d irradiance(const Imath::V3d& point, const Imath::V3d& normal) const;
    // RGB radiant intensity (per steradian) of the far-field point light toward `direction`.
    Imath::V3d farIntensity(const Imath::V3d& direction) const;
    // One sample point's map, decoded.
    std::vector<Imath::V3f> map(std::uint64_t index) const;
    // One sample point's map averaged to face size `faceSize` (as incidentRadiance), before
    // the clamp to 0: the terms a weighted sum of maps adds up, since interpolation is linear.
    std::vector<Imath::V3f> mapTerms(std::uint64_t index, std::uint32_t faceSize) const;

private:
    std::vector<Imath::V3f> blend(std::span<const MapWeight> maps, std::uint32_t faceSize) const;
    std::vector<float> blendCoefficients(std::span<const MapWeight> maps, std::uint32_t faceSize) const;
    void requireFaceSize(std::uint32_t faceSize) const;
    std::uint32_t directionSample(std::uint32_t face, std::int32_t u, std::int32_t v) const;
    void addDirectionWeights(std::uint32_t shell, const Imath::V3d& direction, double weight,
                             FieldStencil& stencil) const;
    Imath::V3d integrate(const std::vector<Imath::V3f>& radiance, const Imath::V3d* normal) const;

    const ShadowField& field_;
    CubeMapLayout mapLayout_;
    CubeMapCosineIntegral cosine_;
    std::vector<double> texelSolidAngles_;
};

}  // namespace opal
