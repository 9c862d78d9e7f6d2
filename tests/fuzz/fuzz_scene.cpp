// The scene reader opal-render uses (examples/scene) on arbitrary scene text. The text is
// written as scene.usda beside a tiny baked asset, candle.usda and its sidecar (the example
// scene's reference), so references reach the asset reader. Inputs that could name a file
// outside that folder (an absolute asset path or "..") are skipped. Anything but
// opal::Error escaping readScene is a finding.
#include "examples/scene/scene_reader.h"
#include "schema/error.h"
#include "tests/fuzz/fuzz_scratch.h"

#include <algorithm>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

bool mayLeaveTheFolder(std::string_view text) {
    return text.find("..") != std::string_view::npos || text.find("@/") != std::string_view::npos ||
           text.find("@@@/") != std::string_view::npos;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    const std::filesystem::path assets = std::filesystem::path(OPAL_SOURCE_DIR) / "tests/fuzz/assets";
    // candle.usda and the sidecar it names (candle.<bake id>.opal, or a legacy candle.opal).
    for (const auto& entry : std::filesystem::directory_iterator(assets)) {
        const std::string file = entry.path().filename().string();
        if (file.rfind("candle.", 0) != 0) continue;
        std::filesystem::copy_file(entry.path(), opal::fuzz::scratch().dir() / file,
                                   std::filesystem::copy_options::overwrite_existing);
    }
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    if (mayLeaveTheFolder(text)) {
        return 0;
    }
    std::filesystem::path path = opal::fuzz::scratch().write("scene.usda", data, size);
    try {
        opal::scene::AssetCache assets;  // fresh per input: nothing carries over between runs
        opal::scene::readScene(path, assets);
    } catch (const opal::Error&) {
    }
    return 0;
}
