#include "examples/scene/asset_path.h"

namespace opal::scene {

std::filesystem::path resolveAssetPath(const std::filesystem::path& layerFile, std::string_view assetPath) {
    const std::filesystem::path path(assetPath);
    const std::filesystem::path anchored = path.is_absolute() ? path : layerFile.parent_path() / path;
    return std::filesystem::absolute(anchored).lexically_normal();
}

}  // namespace opal::scene
