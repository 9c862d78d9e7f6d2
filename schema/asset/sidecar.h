// The sidecar `name.opal` of a baked asset (docs/ARCHITECTURE.md#asset; byte layout in
// schema/asset/SIDECAR.md): the parts of a TranslucentAsset too big for the USDA layer — chart
// layout, surface samples, vertex interpolation weights, compressed transfer, environment transfer
// — in an Opal container of kind 'SCAT'. The render mesh, profile basis, default material, editable
// range and bake settings live in the USDA layer; the sidecar's header chunk records what it
// expects of them (SidecarHeader) so the two files can be checked to belong together.
#pragma once

#include "schema/asset/chunk_format.h"
#include "schema/asset/translucent_asset.h"

#include <cstdint>
#include <optional>
#include <filesystem>
#include <string>

namespace opal {

// 2.0: transfer values on a quantization grid, environment values as half planes (1.0
// stored both as float planes). 2.1 adds the optional BKID chunk (the bake identifier),
// 2.2 the optional FBAS chunk, 2.3 the SELF chunk, 2.4 the ENVK chunk, 2.5 the optional
// HARM chunk, 2.6 the optional HARP chunk.
inline constexpr FileKind kSidecarKind{"SCAT", {2, 6}};

// The chunk tags (all required in version 2.0, except BKID: optional, from 2.1).
namespace sidecar_chunk {
inline constexpr ChunkTag kHeader{"HEAD"};
inline constexpr ChunkTag kLayout{"CHRT"};
inline constexpr ChunkTag kSamples{"SMPL"};
inline constexpr ChunkTag kVertexWeights{"VWGT"};
inline constexpr ChunkTag kTransfer{"TRNS"};
inline constexpr ChunkTag kEnvironment{"ENVT"};
inline constexpr ChunkTag kBakeId{"BKID"};
// Optional (2.2): the environment vectors' Fresnel basis, u32 (FresnelBasis); absent: Legendre.
inline constexpr ChunkTag kFresnelBasis{"FBAS"};
// 2.3: where the transfer's self term lives, u32 (SelfTerm); absent: in the transfer.
// Written flagged required when the self term is left to run time: a reader that does not
// know the chunk would render without it, so it must refuse the file instead.
inline constexpr ChunkTag kSelfTerm{"SELF"};
// 2.4: what the environment vectors hold, u32 (EnvironmentVectorKind); absent: the visible
// transport. Written flagged required when they hold the occluded residual: a reader that
// does not know the chunk would light with the residual as if it were the transport.
inline constexpr ChunkTag kEnvironmentKind{"ENVK"};
// Optional (2.5): the exact transfer of the normal harmonics, CompressedTransfer::harmonics.
// Not required: the matrices alone still carry all of the light, less accurately.
inline constexpr ChunkTag kHarmonics{"HARM"};
// Optional (2.6): the same for the 36 functions of a HarmonicSet with its frame (the normal
// harmonics times the position), in place of HARM. A reader before 2.6 skips it and
// renders from the matrices alone; a file holds at most one of the two.
inline constexpr ChunkTag kPositionHarmonics{"HARP"};
}  // namespace sidecar_chunk

struct SidecarWriteOptions {
    int zstdLevel = 3;
};

// What the sidecar expects of the USDA half of the asset.
struct SidecarHeader {
    std::string name;
    double unitsPerMm = 1.0;
    std::uint64_t sampleCount = 0;
    std::uint32_t basisCount = 0;   // K: matrices in the transfer, functions in the basis
    std::uint32_t vertexCount = 0;  // render-mesh vertices the weights are for
    std::uint64_t meshTopologyHash = 0;
    std::optional<std::uint64_t> bakeId;  // the BKID chunk; empty in sidecars baked without one
};

// XXH64 of the render mesh's face vertex counts and indices and its vertex count
// (SIDECAR.md): integers, so it survives the USDA text round trip exactly.
std::uint64_t meshTopologyHash(const RenderMesh& mesh);

// Validates the sidecar parts of `asset` (the same rules readSidecar applies) and writes
// them atomically to `path`. Sparse CSR indices (transfer columns, environment cube-map
// indices) must be strictly ascending within each row. Throws opal::Error naming the
// file and chunk; on error the previous file at `path` is untouched.
void writeSidecar(const std::filesystem::path& path, const TranslucentAsset& asset,
                  const SidecarWriteOptions& options = {});

// Reads and validates `path`, then fills asset.layout, samples, vertexWeights, transfer
// and environment (all or nothing: on error `asset` is unchanged). Returns the header for
// checkSidecarMatches. Throws opal::Error naming the file and chunk.
SidecarHeader readSidecar(const std::filesystem::path& path, TranslucentAsset& asset);

// Rounds the transfer and environment values to what the sidecar stores of them (the
// transfer's value grids, transfer_value_grid.h; half planes for the environment,
// array_codec.h), so that a bake measures and keeps exactly what it writes.
void roundToStoredPrecision(TranslucentAsset& asset);

// Throws unless the header matches the USDA half of `asset`: name, unitsPerMm, K ==
// basis.K(), vertexCount == mesh.points.size(), mesh topology hash.
void checkSidecarMatches(const SidecarHeader& header, const TranslucentAsset& asset,
                         const std::filesystem::path& sidecarPath);

}  // namespace opal
