// Baked translucent assets loaded once per file: a scene that references candle.usda ten
// times (or two scenes a viewer opens in turn) reads its layer and sidecar once. The
// cache belongs to its host; nothing is global.
#pragma once

#include "schema/asset/translucent_asset.h"
#include "schema/usd/usda_layer.h"

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace opal::scene {

class AssetCache {
public:
    // The asset whose layer is `usdaFile` (read with readAsset the first time it is asked
    // for, under its absolute normal path). Throws opal::Error from readAsset; a failed
    // load is not cached.
    std::shared_ptr<const TranslucentAsset> load(const std::filesystem::path& usdaFile);
    // The asset a prim applying OpalSubsurfaceAPI carries (a scene's Mesh composed from an
    // over-layer), its sidecar resolved against `anchorFile` (readAsset(prim, ...)); cached
    // under the sidecar's absolute normal path, which names the bake.
    std::shared_ptr<const TranslucentAsset> load(const usda::Prim& prim, const std::filesystem::path& anchorFile);

    // What reading the assets warned about (an asset that should be re-baked), once per
    // asset file, since the last call.
    std::vector<std::string> takeWarnings();

    std::size_t size() const { return assets_.size(); }
    // How many loads read files (the rest came from the cache).
    std::size_t reads() const { return reads_; }

private:
    std::map<std::filesystem::path, std::shared_ptr<const TranslucentAsset>> assets_;
    std::size_t reads_ = 0;
    std::vector<std::string> warnings_;
};

}  // namespace opal::scene
