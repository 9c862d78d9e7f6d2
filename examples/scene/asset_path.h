// Asset paths (@...@) in a scene layer are anchored at the layer, as USD's default
// resolver anchors "./x" and "../x": relative paths resolve against the directory of
// the layer that authors them, absolute paths stay as they are.
#pragma once

#include <filesystem>
#include <string_view>

namespace opal::scene {

// The file `assetPath` (as authored in `layerFile`) names, made absolute and normal.
std::filesystem::path resolveAssetPath(const std::filesystem::path& layerFile, std::string_view assetPath);

}  // namespace opal::scene
