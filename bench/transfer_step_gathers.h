// The transfer's L replayed step by step over an asset's samples, so that an image's error
// can be split between the steps that make it (docs/ARCHITECTURE.md#compression):
//
//   lossless   L = (1/pi) (sum_k s_k T_k E + R_disk E): the profile basis alone, every
//              pair of samples, T_k[o][i] = b_k(|x_o - x_i|) A_i as the bake evaluates it
//              (bake/transfer_row.h); the error against the exact dipole gather is the
//              basis's
//   step 1     the same with each row of T_k cut to the Haar coefficients the bake's step 1
//              keeps (bake/transfer_stages.h compressRows), multiplied by E's Haar
//              coefficients (of E's residual after its smooth part when the asset has the
//              harmonic transfer, whose exact product is added, as the engine does); the
//              error against `lossless` is step 1's
//
// What the engine adds beyond `step 1` is step 2 and the stored values' precision. s_k and
// the self term are the engine's (ProfileProjection of the clamped material; R_disk when
// the asset leaves the self term to run time). Each costs a bake's step 1 over its outputs:
// O(N K) per output, O(N^2 K) for all (memory O(block x K x kept)), parallel with TBB.
#pragma once

#include "bake/transfer_builder.h"
#include "schema/asset/translucent_asset.h"

#include <cstdint>
#include <span>
#include <vector>

namespace opal::bench {

// The lossless transfer's L at `outputs` (ascending samples; every sample when empty),
// outputs x 3. irradiance: E per sample, samples x 3 (the engine's E for the material's
// eta). O(N K) per output. Throws opal::Error for a mismatched irradiance, an output out of
// range or an asset whose self term lives in its transfer (sidecars before 2.3).
std::vector<float> losslessGather(const TranslucentAsset& asset, const Material& material,
                                  std::span<const float> irradiance, std::span<const std::uint32_t> outputs = {});

// Step 1's L at `outputs` as losslessGather, replaying step 1 with `settings` (the asset
// records its keep fraction but not its floor: pass the bake's). Throws as losslessGather.
std::vector<float> step1Gather(const TranslucentAsset& asset, const Material& material,
                               std::span<const float> irradiance, const TransferSettings& settings,
                               std::span<const std::uint32_t> outputs = {});

}  // namespace opal::bench
