// Bakes a mesh for a benchmark with the bake library (bake/bake_pipeline.h), or reuses the
// bake an earlier run left in the cache folder. A cached bake is reused only when its key
// (every option that shapes the asset) matches the request, so that a change of the
// shipped defaults bakes again instead of measuring a stale asset.
#pragma once

#include "bake/bake_pipeline.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <memory>
#include <string>

namespace opal::bench {

struct CachedBake {
    std::shared_ptr<const TranslucentAsset> asset;
    std::filesystem::path layer;    // the cached STEM.usda
    nlohmann::ordered_json report;  // opal-bake's JSON report of the bake (bake/bake_report.h)
    bool reused = false;            // read from the cache rather than baked now
};

// A short label for a bake input: the file's stem, or the name after "builtin:".
std::string bakeLabel(const std::string& input);

// name: a short label for the cache's file names (e.g. "bunny"). The stem is
// cacheDir/NAME-SAMPLES, with -kKEEP-eENERGY appended when the transfer settings are not
// the shipped defaults. Throws opal::Error naming the mesh when the bake fails.
CachedBake bakeOrReuse(const BakeOptions& options, const std::string& name, const std::filesystem::path& cacheDir);

}  // namespace opal::bench
