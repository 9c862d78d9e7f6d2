// Interpolation weights from surface samples to render-mesh vertices: the renderer
// computes scattered radiance at the samples and shades the mesh from its vertices.
//
// Each vertex takes its `neighbours` nearest samples whose normals agree with its own
// (n_v . n_s > minNormalAgreement), so light does not bleed through thin parts to the
// other side, with Gaussian weights exp(-d^2 / h^2) at the sample spacing h = sqrt(A / N),
// normalized to sum to 1. A vertex with no agreeing sample among its nearest falls back to
// its single nearest sample.
#pragma once

#include "schema/asset/translucent_asset.h"

#include <cstdint>
#include <span>

namespace opal {

struct VertexWeightOptions {
    std::uint32_t neighbours = 8;
    float minNormalAgreement = 0.5f;
    std::uint32_t searched = 32;  // nearest samples examined for agreeing normals
};

// Samples are referred to by their index in `samples` (store them in grid order first).
// Throws opal::Error for a mesh without normals, no samples, or zero sample area.
VertexWeights computeVertexWeights(const RenderMesh& mesh, std::span<const SurfaceSample> samples,
                                   const VertexWeightOptions& options = {});

}  // namespace opal
