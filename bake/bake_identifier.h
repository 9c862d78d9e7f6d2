// The identifier of a bake (schema/asset/bake_id.h), recorded in both halves of the asset
// it writes. It is XXH64 of a text (bakeIdentity) that lists, one fact a line, what
// determines the result: the tool's version and the sidecar format's, the input as named
// and XXH64 of its bytes (a .gltf may keep its geometry in other files, so the render mesh
// made from it is hashed too), and every resolved setting that changes what is written
// (scheme, level, samples, units, range, default material, K, both compression steps, the
// environment transfer, the seed). What only changes how the work runs (threads, progress
// output, --json, --quiet, or a future split of the work into shards) is never listed:
// identical bakes get the same identifier and stay byte-identical, whoever runs them.
#pragma once

#include "bake/bake_pipeline.h"
#include "schema/asset/translucent_asset.h"

#include <cstdint>
#include <string>

namespace opal {

// The facts of a finished bake of `options` whose in-memory result is `asset`. Throws
// opal::Error naming the input when its bytes cannot be read.
std::string bakeIdentity(const BakeOptions& options, const TranslucentAsset& asset);

std::uint64_t bakeIdentifier(const BakeOptions& options, const TranslucentAsset& asset);

// The lines of bakeIdentity that come from the options alone (the sidecar format, K, both
// compression steps, the environment transfer, the seed): what a cache of bakes keys on
// besides the input and the mesh settings.
std::string compressionIdentity(const BakeOptions& options);

}  // namespace opal
