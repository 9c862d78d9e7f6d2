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

std::shared_ptr<const TranslucentAsset> AssetCache::load(const usda::Prim& prim,
                                                        const std::filesystem::path& anchorFile) {
    const std::string* sidecar = prim.findValue<usda::types::Asset>("opal:sidecar");
    const std::filesystem::path key =
        sidecar ? std::filesystem::absolute(anchorFile.parent_path() / *sidecar).lexically_normal()
                : std::filesystem::path();
    if (const auto it = assets_.find(key); sidecar && it != assets_.end()) return it->second;
    ++reads_;
    auto asset = std::make_shared<const TranslucentAsset>(readAsset(prim, anchorFile, &warnings_));
    assets_.emplace(key, asset);
    return asset;
}

std::vector<std::string> AssetCache::takeWarnings() {
    std::vector<std::string> warnings;
    warnings.swap(warnings_);
    return warnings;
}

}  // namespace opal::scene
