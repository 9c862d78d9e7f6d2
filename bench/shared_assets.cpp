#include "bench/shared_assets.h"

#include <cstdlib>

namespace opal::bench {

std::filesystem::path sharedAssets() {
    if (const char* env = std::getenv("OPAL_SHARED_ASSETS"); env && *env) return env;
    return std::filesystem::path(__FILE__).parent_path().parent_path().parent_path() / "shared" / "assets";
}

std::filesystem::path studioDomeMap() { return sharedAssets() / "envmaps" / "studio_small_05_1k.hdr"; }

}  // namespace opal::bench
