// Bakes a local light for a benchmark as `opal-bake light SPEC` does (bake/light/light_bake.h,
// shipped field settings), or reuses the bake an earlier run left in the cache folder. The
// stem is cacheDir/light-<bake id>: the identifier hashes the tool's version, the sidecar
// format, the emitter and every field setting, so a change of any of them bakes again.
#pragma once

#include "bake/light/emitter.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace opal::bench {

struct CachedLight {
    Emitter emitter;                // the spec's emitter (for direct integration)
    std::filesystem::path sidecar;  // the light sidecar the delegate reads
    nlohmann::ordered_json report;  // opal-bake light's JSON report of the bake (time, sizes, errors)
    bool reused = false;
};

// Throws opal::Error for a bad spec, or naming the stem when the bake or its report fails.
CachedLight bakeLightOrReuse(const std::string& spec, const std::filesystem::path& cacheDir, bool rebake);

}  // namespace opal::bench
