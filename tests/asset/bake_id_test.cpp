// The bake identifier in both halves of an asset: its text form, the round trip through
// the layer (opal:bakeId) and the sidecar (BKID), readAsset refusing halves of different
// bakes, and assets baked before identifiers existed (a real one, written by opal-bake
// before this change: tests/asset/legacy) loading with one warning.
#include "schema/asset/asset_layer.h"
#include "schema/asset/bake_id.h"
#include "schema/asset/sidecar.h"
#include "schema/error.h"
#include "tests/asset/test_files.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace opal {
namespace {
using test::expectContains;
using test::errorOf;

const std::filesystem::path kLegacy = std::filesystem::path(OPAL_SOURCE_DIR) / "tests/asset/legacy/candle.usda";

std::string textOf(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// A complete asset to write in any combination: the legacy one, read back.
TranslucentAsset legacyAsset() {
    std::vector<std::string> ignored;
    return readAsset(kLegacy, &ignored);
}

// Writes `layerAsset`'s layer naming "pair.opal" and `sidecarAsset`'s sidecar as it.
std::filesystem::path writePair(const test::TempDir& dir, const TranslucentAsset& layerAsset,
                                const TranslucentAsset& sidecarAsset) {
    writeSidecar(dir / "pair.opal", sidecarAsset);
    writeAssetLayer(dir / "pair.usda", layerAsset, "./pair.opal");
    return dir / "pair.usda";
}

TEST(BakeId, IsSixteenLowercaseHexDigits) {
    EXPECT_EQ(formatBakeId(0x0123456789abcdefull), "0123456789abcdef");
    EXPECT_EQ(formatBakeId(0), "0000000000000000");
    EXPECT_EQ(parseBakeId("0123456789abcdef"), 0x0123456789abcdefull);
    EXPECT_EQ(parseBakeId("ffffffffffffffff"), ~0ull);
    for (const char* bad : {"", "0123456789abcde", "0123456789abcdef0", "0123456789ABCDEF", "0123456789abcdeg",
                            "-123456789abcdef"})
        EXPECT_FALSE(parseBakeId(bad).has_value()) << bad;
}

TEST(BakeId, ALegacyAssetLoadsWithOneWarningToReBakeIt) {
    std::vector<std::string> warnings;
    const TranslucentAsset asset = readAsset(kLegacy, &warnings);
    EXPECT_FALSE(asset.bake.identifier.has_value());
    EXPECT_EQ(asset.samples.size(), 16u);
    ASSERT_EQ(warnings.size(), 1u);
    expectContains(warnings[0], {kLegacy.string(), "candle.opal", "bake identifier", "re-bake"});
}

TEST(BakeId, BothHalvesCarryTheIdentifierAndNothingIsWarned) {
    const test::TempDir dir;
    TranslucentAsset asset = legacyAsset();
    asset.bake.identifier = 0x8badf00ddeadbeefull;
    const std::filesystem::path usda = writePair(dir, asset, asset);

    const std::string text = textOf(usda);
    EXPECT_NE(text.find("uniform string opal:bakeId = \"8badf00ddeadbeef\""), std::string::npos) << text;
    TranslucentAsset sidecarOnly;
    EXPECT_EQ(readSidecar(dir / "pair.opal", sidecarOnly).bakeId, 0x8badf00ddeadbeefull);

    std::vector<std::string> warnings;
    EXPECT_EQ(readAsset(usda, &warnings).bake.identifier, 0x8badf00ddeadbeefull);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
}

// The case the older checks let through: the same mesh, name, units and K (a re-bake with
// another --material or --range), so only the identifiers tell the halves apart.
TEST(BakeId, HalvesOfDifferentBakesOfTheSameMeshAreRefused) {
    const test::TempDir dir;
    TranslucentAsset layerHalf = legacyAsset(), sidecarHalf = legacyAsset();
    layerHalf.bake.identifier = 0x1111111111111111ull;
    sidecarHalf.bake.identifier = 0x2222222222222222ull;
    const std::filesystem::path usda = writePair(dir, layerHalf, sidecarHalf);
    expectContains(errorOf([&] { readAsset(usda); }),
                   {"sidecar and layer are not from the same bake", usda.string(), (dir / "pair.opal").string(),
                    "1111111111111111", "2222222222222222"});
}

TEST(BakeId, AnIdentifierInOnlyOneHalfIsRefused) {
    const test::TempDir dir;
    TranslucentAsset with = legacyAsset(), without = legacyAsset();
    with.bake.identifier = 0x3333333333333333ull;
    expectContains(errorOf([&] { readAsset(writePair(dir, with, without)); }),
                   {"not from the same bake", "3333333333333333", "has bake id none"});
    expectContains(errorOf([&] { readAsset(writePair(dir, without, with)); }),
                   {"not from the same bake", "has bake id none", "3333333333333333"});
}

TEST(BakeId, AMalformedLayerIdentifierNamesItsPlace) {
    const test::TempDir dir;
    TranslucentAsset asset = legacyAsset();
    asset.bake.identifier = 0x4444444444444444ull;
    const std::filesystem::path usda = writePair(dir, asset, asset);
    std::string edited = textOf(usda);
    const std::size_t at = edited.find("4444444444444444");
    ASSERT_NE(at, std::string::npos);
    edited.replace(at, 16, "44444444444444XY");
    std::ofstream(usda, std::ios::trunc) << edited;
    expectContains(errorOf([&] { readAsset(usda); }), {usda.string() + ":", "opal:bakeId", "44444444444444XY"});
}

}  // namespace
}  // namespace opal
