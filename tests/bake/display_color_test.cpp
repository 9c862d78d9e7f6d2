// The preview colour a baked asset's layer carries for hosts without Opal (display_color.h),
// at the shipped bake defaults: ACEScg -> Rec.709 against the published matrix, an
// unoccluded vertex shows the material's diffuse albedo (the artist albedo it was made
// from), the melt pool of the candle is darker by the sky its rim hides, and the layer
// holds one colour per point with vertex interpolation.
#include "bake/bake_pipeline.h"
#include "schema/asset/asset_layer.h"
#include "schema/asset/display_color.h"
#include "schema/scatter/material.h"
#include "schema/usd/usda_reader.h"
#include "schema/usd/usda_writer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace opal {
namespace {

TEST(DisplayColor, AcescgToRec709IsThePublishedMatrix) {
    // ACEScg -> linear sRGB (Bradford), as OCIO's ACES configs give it, by columns.
    const double published[3][3] = {{1.70505, -0.62179, -0.08326}, {-0.13026, 1.14080, -0.01055},
                                    {-0.02400, -0.12897, 1.15297}};
    for (int j = 0; j < 3; ++j) {
        Imath::V3d primary(0.0);
        primary[j] = 1.0;
        const Imath::V3d out = rec709FromAcescg(primary);
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(out[i], published[i][j], 2e-3) << "row " << i << " column " << j;
    }
    // White stays white, up to the two matrices' D65 (the sRGB standard's 4-digit white
    // against the chromaticity the ACEScg matrix adapts from): measured 2.4e-4 at most.
    const Imath::V3d white = rec709FromAcescg(Imath::V3d(1.0));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(white[i], 1.0, 5e-4);
}

class BakedCandleColors : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        BakeOptions options;  // the shipped defaults, apart from a small sample count
        options.input = "builtin:candle";
        options.samples = 2048;
        ArtistMaterial artist;
        artist.albedo = Rgb(0.8, 0.6, 0.4);
        artist.meanFreePath = Rgb(2.0, 1.0, 0.5);
        material_ = new Material(fromArtist(artist));
        asset_ = new TranslucentAsset(bakeAsset(options, nullptr, CancelToken{}, nullptr));
        asset_->defaultMaterial = *material_;
        colors_ = new std::vector<Imath::V3f>(displayColors(*asset_));
    }
    static void TearDownTestSuite() {
        delete colors_;
        delete asset_;
        delete material_;
    }
    // The median over the vertices `pick` chooses of colour / expected, per channel.
    template <class Pick>
    static Imath::V3d medianRatio(Pick&& pick, const Imath::V3d& expected) {
        std::array<std::vector<double>, 3> ratios;
        for (std::size_t v = 0; v < colors_->size(); ++v)
            if (pick(asset_->mesh.points[v], asset_->mesh.normals[v]))
                for (int c = 0; c < 3; ++c) ratios[c].push_back((*colors_)[v][c] / expected[c]);
        Imath::V3d median;
        for (int c = 0; c < 3; ++c) {
            EXPECT_GT(ratios[c].size(), 8u);
            std::nth_element(ratios[c].begin(), ratios[c].begin() + ratios[c].size() / 2, ratios[c].end());
            median[c] = ratios[c][ratios[c].size() / 2];
        }
        return median;
    }
    static inline Material* material_ = nullptr;
    static inline TranslucentAsset* asset_ = nullptr;
    static inline std::vector<Imath::V3f>* colors_ = nullptr;
};

TEST_F(BakedCandleColors, AnUnoccludedWallShowsTheMaterialsAlbedo) {
    ASSERT_EQ(colors_->size(), asset_->mesh.points.size());
    const Imath::V3d albedo = rec709FromAcescg(Imath::V3d(0.8, 0.6, 0.4));
    const Imath::V3d wall = medianRatio(
        [](const Imath::V3f& p, const Imath::V3f& n) { return std::abs(n.y) < 0.2f && p.y > 20.0f && p.y < 60.0f; },
        albedo);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(wall[c], 1.0, 0.03) << "channel " << c;
}

TEST_F(BakedCandleColors, ThePoolIsDarkerByTheSkyItsRimHides) {
    // From the pool's centre the rim rises about atan(5 / 18.2) = 15 degrees above the
    // horizon all around: a cosine-weighted sky of 1 - sin^2(15.4 deg) = 0.93 of the open one.
    const Imath::V3d albedo = rec709FromAcescg(Imath::V3d(0.8, 0.6, 0.4));
    const Imath::V3d pool = medianRatio(
        [](const Imath::V3f& p, const Imath::V3f& n) { return n.y > 0.95f && p.x * p.x + p.z * p.z < 16.0f; },
        albedo);
    const double open = std::pow(std::sin(std::atan(5.0 / 18.2)), 2.0);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(pool[c], 1.0 - open, 0.03) << "channel " << c;
}

TEST_F(BakedCandleColors, TheLayerCarriesOneColourPerPointInterpolatedByVertex) {
    TranslucentAsset asset = *asset_;
    const usda::Layer written = usda::readUsda(usda::writeUsda(assetToLayer(asset, "./candle.opal")), "candle.usda");
    const usda::Attribute& color = written.rootPrims.front().attribute("primvars:displayColor");
    EXPECT_EQ(color.get<usda::types::Color3fArray>().size(), asset.mesh.points.size());
    EXPECT_EQ(color.metadata.find("interpolation")->get<usda::types::Token>("interpolation"), "vertex");
}

}  // namespace
}  // namespace opal
