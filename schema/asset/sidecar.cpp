// The link between a sidecar and the USDA layer it belongs to.
#include "schema/asset/sidecar.h"

#include "schema/asset/array_codec.h"
#include "schema/asset/chunked_file.h"
#include "schema/asset/transfer_value_grid.h"
#include "schema/asset/little_endian.h"
#include "schema/asset/xxhash64.h"
#include "schema/error.h"

#include <bit>
#include <cmath>

namespace opal {
namespace {

static_assert(std::endian::native == std::endian::little, "int32 arrays are hashed as their in-memory bytes");

void hashArray(Xxh64& hash, std::span<const std::int32_t> values) {
    std::vector<std::byte> count;
    le::put(count, std::uint64_t(values.size()));
    hash.update(count);
    hash.update(std::as_bytes(values));
}

}  // namespace

std::uint64_t meshTopologyHash(const RenderMesh& mesh) {
    Xxh64 hash;
    std::vector<std::byte> vertices;
    le::put(vertices, std::uint64_t(mesh.points.size()));
    hash.update(vertices);
    hashArray(hash, mesh.faceVertexCounts);
    hashArray(hash, mesh.faceVertexIndices);
    return hash.digest();
}

void roundToStoredPrecision(TranslucentAsset& asset) {
    const TransferValueGrid grid(asset.layout);
    for (std::size_t k = 0; k < asset.transfer.perBasis.size(); ++k)
        grid.round(asset.transfer.perBasis[k], asset.transfer.valueStep(k));
    roundToHalfPlanes(asset.environment.values);
}

void checkSidecarMatches(const SidecarHeader& header, const TranslucentAsset& asset,
                         const std::filesystem::path& sidecarPath) {
    std::string where = chunkContext(sidecarPath, sidecar_chunk::kHeader) + ": ";
    std::string hint = " (sidecar and layer are not from the same bake)";
    if (header.name != asset.name)
        throw Error(where + "asset name '" + header.name + "', the layer says '" + asset.name + "'" + hint);
    if (std::abs(header.unitsPerMm - asset.unitsPerMm) > 1e-9 * std::abs(asset.unitsPerMm))
        throw Error(where + "unitsPerMm " + std::to_string(header.unitsPerMm) + ", the layer says " +
                    std::to_string(asset.unitsPerMm) + hint);
    if (header.basisCount != static_cast<std::uint32_t>(asset.basis.K()))
        throw Error(where + "K = " + std::to_string(header.basisCount) + ", the layer's profile basis has " +
                    std::to_string(asset.basis.K()) + " functions" + hint);
    if (header.vertexCount != asset.mesh.points.size())
        throw Error(where + "weights for " + std::to_string(header.vertexCount) + " vertices, the render mesh has " +
                    std::to_string(asset.mesh.points.size()) + hint);
    if (header.meshTopologyHash != meshTopologyHash(asset.mesh))
        throw Error(where + "the render mesh's faces differ from the ones the sidecar was baked for" + hint);
}

}  // namespace opal
