// Material edits stay within the asset's editable range (the range the bake's PCA basis
// holds), and the reset restores what the bake recorded.
#include "examples/opal-view/core/material_edit.h"
#include "schema/error.h"

#include <gtest/gtest.h>

#include <vector>

namespace opal::view {
namespace {

TranslucentAsset rangedAsset() {
    TranslucentAsset asset;
    asset.defaultMaterial = Material{{1.2, 0.9, 0.7}, {0.05, 0.1, 0.2}, 1.4};
    asset.range = EditableRange{0.5, 3.0, 0.01, 0.4, 1.2, 1.6};
    return asset;
}

std::string errorOf(std::string_view parameter, std::vector<double> values) {
    try {
        withParameter({}, parameter, values, rangedAsset());
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(MaterialEdit, SetsOneParameterAndKeepsTheRest) {
    const TranslucentAsset asset = rangedAsset();
    const hd::MaterialDesc start = bakedDefault(asset);
    const std::vector<double> absorption = {0.3, 0.1, 0.3};
    const hd::MaterialDesc edited = withParameter(start, "sigma_a", absorption, asset);
    EXPECT_EQ(edited.subsurface.sigmaA, (Rgb{0.3, 0.1, 0.3}));
    EXPECT_EQ(edited.subsurface.sigmaSPrime, start.subsurface.sigmaSPrime);
    EXPECT_EQ(edited.subsurface.eta, 1.4);
    const std::vector<double> rough = {0.6};
    EXPECT_EQ(withParameter(edited, "roughness", rough, asset).specularRoughness, 0.6);
    const std::vector<double> eta = {1.5};
    EXPECT_EQ(withParameter(edited, "eta", eta, asset).subsurface.eta, 1.5);
}

TEST(MaterialEdit, TheBakedDefaultIsTheAssetsMaterialWithTheDefaultSpecularLayer) {
    const hd::MaterialDesc reset = bakedDefault(rangedAsset());
    EXPECT_EQ(reset.subsurface.sigmaA, (Rgb{0.05, 0.1, 0.2}));
    EXPECT_EQ(reset.subsurface.sigmaSPrime, (Rgb{1.2, 0.9, 0.7}));
    EXPECT_TRUE(reset.specular);
    EXPECT_EQ(reset.specularRoughness, hd::MaterialDesc{}.specularRoughness);
}

TEST(MaterialEdit, ValuesOutsideTheEditableRangeAreRefusedNamingChannelAndRange) {
    EXPECT_EQ(errorOf("sigma_a", {0.1, 0.5, 0.1}), "sigma_a (green, mm^-1) 0.5 is outside the asset's editable range [0.01, 0.4]");
    EXPECT_EQ(errorOf("sigma_s", {0.4, 1, 1}), "sigma_s' (red, mm^-1) 0.4 is outside the asset's editable range [0.5, 3]");
    EXPECT_EQ(errorOf("eta", {1.7}), "eta 1.7 is outside the asset's editable range [1.2, 1.6]");
    EXPECT_EQ(errorOf("roughness", {1.5}), "specular roughness 1.5 is outside the asset's editable range [0, 1]");
    EXPECT_EQ(errorOf("sigma_a", {0.1}), "sigma_a takes 3 value(s), got 1");
}

}  // namespace
}  // namespace opal::view
