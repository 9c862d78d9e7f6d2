// `opal-bake batch MANIFEST.json`: what to bake. The manifest is
//   {"assets": [{"input": "rock.obj", "output": "baked/rock", "args": ["--samples", "4096"]}, ...]}
// `input` is a mesh file or a built-in mesh (builtin:NAME), `output` the asset's stem; both
// relative to the manifest's folder. `args` (optional) are opal-bake's options for that asset
// (not -o, --json, --quiet or the farm's options, which the batch sets). Every error names the manifest and the
// entry ("assets[3].output").
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace opal {

struct BatchEntry {
    std::string input;                // as opal-bake takes it: a resolved path or builtin:NAME
    std::filesystem::path output;     // resolved stem
    std::vector<std::string> args;
};

// Throws opal::Error for an unreadable file, bad JSON, a missing or mistyped field, an
// option the batch sets itself, or two entries writing one stem.
std::vector<BatchEntry> readBatchManifest(const std::filesystem::path& manifest);

}  // namespace opal
