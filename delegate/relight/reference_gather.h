// The exact dipole gather over an asset's samples (docs/ARCHITECTURE.md#bssrdf), with neither the
// PCA profile basis nor the wavelet compression: the ground truth the relighting engine is measured
// against, and a reference mode users can select.
//
//   L(x_o) = (1/pi) sum_i R_d(|x_o - x_i|; sigma_s'_c, sigma_a_c, eta) A_i E_c(x_i)
//
// per RGB channel c, with distances in mm and areas in mm^2 (the asset's unitsPerMm). Like
// RelightEngine's output, L lacks the outgoing F_t(eta, w_o). O(N) per output sample,
// parallel over outputs (TBB); O(N^2) for all of them.
#pragma once

#include "schema/asset/translucent_asset.h"

#include <cstdint>
#include <span>
#include <vector>

namespace opal {

// irradiance: E(x_i) per sample, samples x 3 (e.g. MeshIrradiance::exactIrradiance).
// outputs: the samples x_o to evaluate (all when empty). Returns outputs x 3. The material
// is used as given (validated, not clamped: the dipole holds for any material).
std::vector<float> referenceGather(const TranslucentAsset& asset, const Material& material,
                                   std::span<const float> irradiance,
                                   std::span<const std::uint32_t> outputs = {});

}  // namespace opal
