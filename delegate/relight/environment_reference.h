// The true irradiance of a dome light at an asset's samples, for the reference mode
// (opal:reference; docs/ARCHITECTURE.md#dome-reference): per sample x_i and RGB channel c,
//
//   E_c(x_i) = integral over the sphere of L_c(w) V(x_i, w) F_t(eta, n_i.w) max(0, n_i.w) dw
//
// with L the dome's map (EnvironmentLight: its rotation, the mesh's rotation and the scale),
// V the asset's own occlusion and F_t the exact Fresnel transmittance
// (schema/scatter/dipole.h). The engine approximates the same integral with the baked
// transport vectors (a coarser cube map, the largest Haar terms, F_t as Fresnel moments);
// this one has none of those approximations, so the difference is the engine's error.
//
// The quadrature is deterministic: one direction per texel of a cube map finer than the
// bake's (faceSizeFor: max(64, 2 x the bake's face size)), each texel weighted by its solid
// angle, its radiance the map averaged over the texel (EnvironmentLight::cubeRadiance), its
// visibility one Embree occlusion ray through its centre.
//
// Visibility has the engine's semantics (docs/ARCHITECTURE.md#dome-light) so that the
// comparison is fair: V is the asset's own render mesh in object space, occluding itself
// only (other meshes do not shadow a dome), traced as the bake traces it (from the sample
// offset 1e-4 x the mesh's extent along its normal, to infinity).
//
// Visibility does not depend on the dome, the mesh's placement or eta, so it is traced once,
// at construction, and kept as one bit per sample and texel (3 KB per sample at face size
// 64) when that fits kMaxVisibilityBytes: rotating the dome, moving the mesh or editing eta
// then sums again without a ray. Beyond that budget every irradiance() call traces again.
#pragma once

#include "delegate/relight/environment_light.h"
#include "raytrace/ray_scene.h"
#include "schema/asset/cube_map.h"
#include "schema/asset/translucent_asset.h"

#include <Imath/ImathMatrix.h>

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace opal {

class EnvironmentReference {
public:
    // Visibility kept between calls up to this many bytes (see above).
    static constexpr std::size_t kMaxVisibilityBytes = std::size_t(256) << 20;
    static constexpr std::uint32_t kMinFaceSize = 64;

    // max(kMinFaceSize, 2 x the bake's cube face size), at most CubeMapLayout::kMaxFaceSize.
    static std::uint32_t faceSizeFor(const TranslucentAsset& asset);

    // Builds the asset's occlusion scene and, when samples x texels bits fit visibilityBudget
    // bytes, traces and keeps every sample's visibility. faceSize: a power of two up to
    // CubeMapLayout::kMaxFaceSize (opal::Error otherwise).
    EnvironmentReference(std::shared_ptr<const TranslucentAsset> asset, std::uint32_t faceSize,
                         std::size_t visibilityBudget = kMaxVisibilityBytes);

    std::uint32_t faceSize() const { return cube_.faceSize(); }
    bool visibilityCached() const { return !visibility_.empty(); }

    // E(x_i) for every sample of the asset placed by objectToWorld (only its rotation
    // matters: the dome is infinitely far): samples x 3. Throws opal::Error for an eta
    // that is not positive and finite.
    std::vector<float> irradiance(const EnvironmentLight& dome, const Imath::M44d& objectToWorld, double eta) const;

    std::size_t memoryBytes() const;

private:
    struct TraceScratch;  // one thread's ray buffers
    // Bit t of `bits` (wordsPerSample() words): sample i sees the centre of texel t above its
    // horizon.
    void traceVisibility(std::size_t i, std::span<std::uint64_t> bits, TraceScratch& scratch) const;
    // One sample's E over the texels its bits mark: radiance is texels x 3.
    void sampleIrradiance(const Imath::V3f& normal, std::span<const std::uint64_t> bits, std::span<const float> radiance,
                          double eta, std::span<float, 3> e) const;
    std::size_t wordsPerSample() const { return (std::size_t(cube_.texels()) + 63) / 64; }

    std::shared_ptr<const TranslucentAsset> asset_;
    CubeMapLayout cube_;
    std::vector<Imath::V3f> directions_;  // per texel, unit, object space
    std::vector<double> solidAngles_;     // per texel, steradians
    RayScene scene_;                      // the asset's render mesh, object space
    float offset_ = 0.0f;
    std::vector<std::uint64_t> visibility_;  // samples x wordsPerSample(); empty beyond the budget
};

}  // namespace opal
