// Asset names are prim names: both halves of an asset record the name, and the layer can
// only hold an identifier, so anything else is refused rather than silently renamed.
#include "schema/asset/asset_layer.h"

#include "schema/error.h"
#include "tests/asset/synthetic_asset.h"

#include <gtest/gtest.h>

namespace opal {
namespace {

TEST(AssetName, FileStemsBecomePrimNames) {
    EXPECT_EQ(assetNameFrom("stanford-bunny_watertight_quartet"), "stanford_bunny_watertight_quartet");
    EXPECT_EQ(assetNameFrom("3d scan.v2"), "_3d_scan_v2");
    EXPECT_EQ(assetNameFrom(""), "_");
    EXPECT_EQ(assetNameFrom("candle"), "candle");
}

TEST(AssetName, TheLayerRefusesANameThatIsNoPrimName) {
    TranslucentAsset asset = test::syntheticAsset();
    asset.name = "stanford-bunny";
    try {
        (void)assetToLayer(asset, "./x.opal");
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("'stanford_bunny'"), std::string::npos) << e.what();
    }
    asset.name = "stanford_bunny";
    EXPECT_EQ(assetToLayer(asset, "./x.opal").rootPrims.at(0).name, "stanford_bunny");
}

}  // namespace
}  // namespace opal
