#include "examples/scene/asset_cache.h"

#include "schema/asset/asset_layer.h"

namespace opal::scene {

std::shared_ptr<const TranslucentAsset> AssetCache::load(const std::filesystem::path& usdaFile) {
    const std::filesystem::path key = std::filesystem::absolute(usdaFile).lexically_normal();
    if (const auto it = assets_.find(key); it != assets_.end()) return it->second;
    ++reads_;
    auto asset = std::make_shared<const TranslucentAsset>(readAsset(key, &warnings_));
    assets_.emplace(key, asset);
    return asset;
}

std::vector<std::string> AssetCache::takeWarnings() {
    std::vector<std::string> warnings;
    warnings.swap(warnings_);
    return warnings;
}

}  // namespace opal::scene
