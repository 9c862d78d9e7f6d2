// The asset's baked environment vectors (docs/ARCHITECTURE.md#dome-light), laid out for the one
// operation a dome edit waits for: E_m(x_i) += <T_{i,m}, L> for every sample i and moment m, RGB,
// with T the visible transport, or E_m(x_i) += U_m(n_i) - <O_{i,m}, L> with O the occluded
// residual (EnvironmentTransfer::kind) and U the dome's unoccluded integral (dome_convolution.h).
//
// The sidecar stores one sparse row per (sample, m); the bake keeps the same Haar
// positions for every m of a sample (bake/environment_visibility.h). Here each sample has
// one list of positions, the union of its m rows, with the m values side by side (zero
// where a row lacks the position), so one gather of L serves every m. Positions are 16-bit
// when the cube map has at most 65,536 texels (every face size up to 104), else 32, and
// values are scaled binary16 (scaled_half.h) with one scale per m. The sidecar already
// stores these values as binary16 with one scale for all (schema/asset/array_codec.h), so
// a loaded asset's values come through exactly, but for those below 2^-28 of the largest.
// On the 65,536-sample bunny (m = 2), with 128 visible-transport terms, a dome edit streamed
// 50 MB here instead of the asset's 134 MB, and the sums took (2 cores, medians): asset rows
// 8-11 ms, this layout portable 7.6 ms, with FMA + F16C 3.7 ms; the occluded residuals of
// sidecar 2.4 average 358 terms per sample there and take 9.3 ms. Two moments (the bake's
// default) take their own loop, one fused multiply-add per entry for both
// (sampleAvx2TwoMoments; its measurements are beside it).
#pragma once

#include "delegate/relight/compact_indices.h"
#include "delegate/relight/dome_convolution.h"
#include "delegate/relight/irradiance.h"
#include "schema/asset/translucent_asset.h"

#include <Imath/ImathMatrix.h>

#include <cstdint>
#include <span>
#include <vector>

namespace opal {

class EnvironmentVectors {
public:
    // Throws opal::Error when the transfer is not baked, its rows are not samples x terms,
    // or an index is outside the cube map. useAvx2: take the FMA + F16C loop where the CPU
    // has them (checked at run time); false forces the portable loop (tests compare both).
    EnvironmentVectors(const EnvironmentTransfer& transfer, std::size_t samples, bool useAvx2 = true);

    bool usesAvx2() const { return avx2_; }

    std::uint32_t terms() const { return terms_; }
    std::uint32_t texels() const { return texels_; }
    std::size_t samples() const { return offsets_.size() - 1; }

    EnvironmentVectorKind kind() const { return kind_; }

    // The dome's E_m at every sample, added to `moments`: radiance is the dome on the cube
    // map in object space, texels x 3 (EnvironmentLight::cubeRadiance), and samples the
    // asset's (their object-space normals). For occluded vectors, `open` is the dome map's
    // unoccluded integral in the dome's own frame (EnvironmentLight::domeCubeMap), read at
    // each normal turned by domeFromObject (row vectors) and multiplied by the dome's
    // openScale (its colour x intensity x 2^exposure): a rotation or a colour edit needs no
    // new one.
    // Throws opal::Error when the moments, the radiance or the samples do not match, or
    // occluded vectors come without `open`.
    void addDome(std::vector<float> radiance, const DomeConvolution* open, const Imath::V3f& openScale,
                 const Imath::M33d& domeFromObject, std::span<const SurfaceSample> samples,
                 IrradianceMoments& moments);
    // E_m(x_i) += weight <v_{i,m}, L> for the stored vectors v, haarRadiance texels x 3 (the
    // cube radiance Haar transformed per face). Throws opal::Error when the moments or the
    // radiance do not match. Not thread-safe (nor addDome): the radiance is padded to 4
    // floats a texel in a buffer the object keeps for the next call (each mesh's
    // MeshIrradiance owns its vectors and relights its domes one at a time).
    void addIrradiance(std::span<const float> haarRadiance, IrradianceMoments& moments, float weight = 1.0f);

    // Bytes held: the compact vectors and the padded radiance (texels x 4 floats, kept after
    // the first call).
    std::size_t memoryBytes() const {
        return offsets_.capacity() * sizeof(std::uint64_t) + positions_.memoryBytes() +
               halves_.capacity() * sizeof(std::uint16_t) +
               scales_.capacity() * sizeof(float) + padded_.capacity() * sizeof(float);
    }

private:
    template <typename Index, std::uint32_t M>
    void addRows(const Index* positions, const float* radiance, float weight, IrradianceMoments& moments) const;

    std::uint32_t terms_ = 0;
    EnvironmentVectorKind kind_ = EnvironmentVectorKind::Visible;
    FresnelBasis basis_ = FresnelBasis::Legendre;
    std::uint32_t faceSize_ = 0;
    std::uint32_t texels_ = 0;
    bool avx2_ = false;
    std::vector<std::uint64_t> offsets_;      // per sample, into the position lists
    CompactIndices positions_;                // texels, per sample ascending
    std::vector<std::uint16_t> halves_;       // per position, terms binary16 values
    std::vector<float> scales_;               // 2^e per m
    std::vector<float> padded_;               // addIrradiance's radiance, texels x 4 (RGB, 0)
};

}  // namespace opal
