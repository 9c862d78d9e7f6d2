// Baked translucent assets loaded once per file: a scene that references candle.usda ten
// times (or two scenes a viewer opens in turn) reads its layer and sidecar once. The
// cache belongs to its host; nothing is global.
#pragma once

#include "schema/asset/translucent_asset.h"

#include <filesystem>
#include <map>
#include <memory>

namespace opal::scene {

class AssetCache {
public:
    // The asset whose layer is `usdaFile` (read with readAsset the first time it is asked
    // for, under its absolute normal path). Throws opal::Error from readAsset; a failed
    // load is not cached.
    std::shared_ptr<const TranslucentAsset> load(const std::filesystem::path& usdaFile);

    std::size_t size() const { return assets_.size(); }
    // How many loads read files (the rest came from the cache).
    std::size_t reads() const { return reads_; }

private:
    std::map<std::filesystem::path, std::shared_ptr<const TranslucentAsset>> assets_;
    std::size_t reads_ = 0;
};

}  // namespace opal::scene
