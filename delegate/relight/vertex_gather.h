// The render-mesh vertices' radiance from the samples' (docs/ARCHITECTURE.md#vertex-radiance):
// L(v) = sum_i w_vi L(x_i), the asset's VertexWeights, laid out for the one operation a
// material edit waits for after the samples' radiance.
//
// That gather reads each vertex's ~8 samples. In the mesh's own vertex order (OpenSubdiv's,
// level by level) neighbouring vertices read far-apart samples, and the samples (1 MB at
// 65,536, padded to four lanes) do not stay in a core's cache, so every gather waited on
// memory. The vertices are visited in the order of their heaviest sample instead (samples
// lie in chart order, neighbours near each other), with their weights stored in that order:
// the gathers hit the cache, and the scattered writes of three floats a vertex do not stall.
// Sample indices are checked once, when the layout is built.
#pragma once

#include "delegate/relight/compact_indices.h"
#include "delegate/relight/float4.h"
#include "schema/asset/translucent_asset.h"

#include <cstdint>
#include <span>
#include <vector>

namespace opal {

class VertexGather {
public:
    // Throws opal::Error when the offsets are inconsistent or a sample index is not below
    // `samples`.
    VertexGather(const VertexWeights& weights, std::size_t samples);

    std::size_t vertices() const { return vertex_.size(); }
    std::size_t samples() const { return samples_; }

    // out[3 v + c] = sum_i w_vi perSample[3 i + c]. perSample: samples x 3, out: vertices x 3
    // (both checked). scratch holds the samples padded to four lanes between calls, so that a
    // caller gathering on every edit allocates nothing.
    void apply(std::span<const float> perSample, std::span<float> out, std::vector<Float4>& scratch) const;

    // The same for two per-sample signals at once (the radiance and the irradiance, after a
    // light or eta edit): one pass over the weights serves both, which halves the bytes the
    // second gather would read (the weights and sample indices outweigh the samples).
    void apply(std::span<const float> perSampleA, std::span<const float> perSampleB, std::span<float> outA,
               std::span<float> outB, std::vector<Float4>& scratch) const;

    std::size_t memoryBytes() const;

private:
    void checkSizes(std::span<const float> perSample, std::span<const float> out) const;
    // out[s][3 v + c] = sum_i w_vi perSample[s][3 i + c] for the S signals.
    template <int S>
    void gather(const std::span<const float> (&perSample)[S], const std::span<float> (&out)[S],
                std::vector<Float4>& scratch) const;
    template <int S, typename Index>
    void gatherVertices(const Index* sample, const Float4* padded, const std::span<float> (&out)[S]) const;

    std::size_t samples_ = 0;
    std::vector<std::uint32_t> vertex_;   // visiting order: vertex_[i] is the i-th vertex visited
    std::vector<std::uint32_t> offsets_;  // visits + 1, into the sample indices and weight_
    CompactIndices sample_;                // the sample indices
    std::vector<float> weight_;
};

}  // namespace opal
