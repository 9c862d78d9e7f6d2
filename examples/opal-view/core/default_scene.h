// What opal-view opens without an argument: the candle scene the README's main job
// (scripts/run-main) renders, out/candle/candlelight.usda.
#pragma once

#include <filesystem>

namespace opal::view {

// The first that exists of: $OPAL_OUT_DIR/candle/candlelight.usda, out/candle/ under the
// working directory, and out/candle/ of the checkout the executable was built in
// (<checkout>/build/bin/opal-view). Throws opal::Error saying to run scripts/run-main
// first when none does.
std::filesystem::path defaultScene(const std::filesystem::path& executable);

}  // namespace opal::view
