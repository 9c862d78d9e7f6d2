// Bakes cached between benchmark runs (bench/cached_bake.h): a second request reads the
// bake back, and any change of an option that shapes the asset bakes again.
#include "bench/cached_bake.h"

#include "schema/error.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>

namespace opal::bench {
namespace {

namespace fs = std::filesystem;

class CachedBakeTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("opal-cached-bake-" + std::to_string(::getpid()));
        fs::remove_all(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    static BakeOptions small() {
        BakeOptions o;
        o.input = "builtin:candle";
        o.samples = 256;
        return o;
    }

    fs::path dir_;
};

TEST_F(CachedBakeTest, ASecondRequestReadsTheBakeBack) {
    const CachedBake first = bakeOrReuse(small(), "candle", dir_);
    EXPECT_FALSE(first.reused);
    EXPECT_EQ(first.layer, dir_ / "candle-256.usda");
    EXPECT_EQ(first.report.at("samples"), 256);
    const CachedBake second = bakeOrReuse(small(), "candle", dir_);
    EXPECT_TRUE(second.reused);
    EXPECT_EQ(second.report.at("sidecar_bytes"), first.report.at("sidecar_bytes"));
    ASSERT_EQ(second.asset->samples.size(), first.asset->samples.size());
    for (std::size_t i = 0; i < first.asset->samples.size(); ++i)
        EXPECT_EQ(second.asset->samples[i].position, first.asset->samples[i].position);
}

TEST_F(CachedBakeTest, OtherCompressionIsAnotherBake) {
    bakeOrReuse(small(), "candle", dir_);
    BakeOptions o = small();
    o.transfer.keepFraction = 0.05;
    const CachedBake other = bakeOrReuse(o, "candle", dir_);
    EXPECT_FALSE(other.reused);
    EXPECT_EQ(other.layer, dir_ / "candle-256-k0.05-m256-e0.99998.usda");
    EXPECT_EQ(other.asset->transfer.keepFraction, 0.05);
}

TEST_F(CachedBakeTest, AChangedOptionUnderTheSameNameBakesAgain) {
    bakeOrReuse(small(), "candle", dir_);
    BakeOptions o = small();
    o.seed = 2;  // not in the file name: only the key tells the bakes apart
    const CachedBake again = bakeOrReuse(o, "candle", dir_);
    EXPECT_FALSE(again.reused);
    EXPECT_EQ(again.asset->bake.seed, 2u);
    EXPECT_TRUE(bakeOrReuse(o, "candle", dir_).reused);
}

TEST_F(CachedBakeTest, AMissingMeshIsAnErrorNamingIt) {
    BakeOptions o = small();
    o.input = (dir_ / "no-such-mesh.obj").string();
    try {
        bakeOrReuse(o, "none", dir_);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no-such-mesh.obj"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace opal::bench
