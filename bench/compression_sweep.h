// The engine's compression settings `opal-bench relight --sweep-mesh` bakes an asset's mesh
// at, to place the engine on the error-against-time figure beside the peer: each setting is
// a bake of the same mesh, samples, level, scale and seed as the asset, with only the
// transfer's two compression steps changed (TransferSettings: keep per row, energy kept).
#pragma once

#include "bake/bake_pipeline.h"

#include <span>
#include <string>
#include <vector>

namespace opal::bench {

// Step-1 coefficients per row at the default energy (the count alone: the keep fraction at
// its smallest, so at every sample count the count governs), then energies at the shipped
// step-1 budget, in that order, each setting once.
std::vector<TransferSettings> compressionSettings(std::span<const std::uint32_t> perRows,
                                                  std::span<const double> energies);

// The bake of `mesh` that matches `asset` (sample count, subdivision scheme and level,
// units per mm, seed, basis count, editable range, environment settings) at `transfer`.
BakeOptions sweepBakeOptions(const TranslucentAsset& asset, const std::string& mesh, const TransferSettings& transfer);

}  // namespace opal::bench
