#include "examples/opal-view/core/default_scene.h"

#include "schema/error.h"

#include <cstdlib>
#include <vector>

namespace opal::view {

std::filesystem::path defaultScene(const std::filesystem::path& executable) {
    const std::filesystem::path scene = std::filesystem::path("candle") / "candlelight.usda";
    std::vector<std::filesystem::path> candidates;
    if (const char* out = std::getenv("OPAL_OUT_DIR"); out && *out) candidates.push_back(out / scene);
    candidates.push_back("out" / scene);
    candidates.push_back(executable.parent_path().parent_path().parent_path() / "out" / scene);
    std::string tried;
    for (const std::filesystem::path& candidate : candidates) {
        if (std::filesystem::is_regular_file(candidate)) return candidate;
        tried += (tried.empty() ? "" : ", ") + candidate.string();
    }
    throw Error("no scene given and the candle scene is not there (looked for " + tried +
                "): run scripts/run-main first, which bakes the candle and writes that scene, or name a "
                "SCENE.usda or ASSET.usda");
}

}  // namespace opal::view
