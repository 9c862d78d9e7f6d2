// Where the benchmarks find the shared test assets (meshes, the studio HDR map).
#pragma once

#include <filesystem>

namespace opal::bench {

// $OPAL_SHARED_ASSETS, else ../shared/assets beside the source tree.
std::filesystem::path sharedAssets();

// The studio HDR map `opal-bench relight` and `opal-bench accuracy` light the dome with.
std::filesystem::path studioDomeMap();

}  // namespace opal::bench
