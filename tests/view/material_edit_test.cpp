// Material edits stay within the asset's editable range (the range the bake's PCA basis
// holds), and the reset restores what the bake recorded. Albedo and mean free path edits
// convert to coefficients that give them back through the forward formulas: the dipole's
// total diffuse reflectance R_d(sigma_s' / sigma_t', eta) and l_d = 1 / sqrt(3 sigma_a sigma_t').
#include "examples/opal-view/core/material_edit.h"
#include "schema/error.h"
#include "schema/scatter/dipole.h"

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

double forwardAlbedo(const Material& m, int c) {
    return dipoleTotalReflectance(m.sigmaSPrime[c] / (m.sigmaSPrime[c] + m.sigmaA[c]), m.eta);
}

double forwardMeanFreePath(const Material& m, int c) {
    return 1.0 / std::sqrt(3.0 * m.sigmaA[c] * (m.sigmaSPrime[c] + m.sigmaA[c]));
}

TEST(MaterialEdit, AlbedoAndMeanFreePathGiveCoefficientsWhoseForwardFormulasReturnThem) {
    const TranslucentAsset asset = rangedAsset();
    const Material start = asset.defaultMaterial;
    const Rgb scaleAlbedo{1.03, 0.97, 1.02}, scalePath{0.9, 1.1, 1.0};
    std::vector<double> albedo(3), path(3);
    for (int c = 0; c < 3; ++c) {
        albedo[c] = forwardAlbedo(start, c) * scaleAlbedo[c];
        path[c] = forwardMeanFreePath(start, c) * scalePath[c];
    }
    const Material withAlbedo = withParameter(bakedDefault(asset), "albedo", albedo, asset).subsurface;
    const Material withBoth = withParameter({withAlbedo, {}}, "mfp", path, asset).subsurface;
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(forwardAlbedo(withAlbedo, c), albedo[c], 1e-9) << "channel " << c;
        EXPECT_NEAR(forwardMeanFreePath(withAlbedo, c), forwardMeanFreePath(start, c), 1e-9) << "the path is kept";
        EXPECT_NEAR(forwardAlbedo(withBoth, c), albedo[c], 1e-9) << "the albedo is kept";
        EXPECT_NEAR(forwardMeanFreePath(withBoth, c), path[c], 1e-9) << "channel " << c;
    }
    EXPECT_EQ(withBoth.eta, start.eta);
    EXPECT_NE(withAlbedo.sigmaA[0], start.sigmaA[0]) << "the edit changed the coefficients";
}

TEST(MaterialEdit, AnAlbedoOrPathOutsideTheRangeItConvertsToIsRefused) {
    EXPECT_EQ(errorOf("albedo", {0.5, 1.2, 0.5}).find("fromArtist: albedo"), 0u) << errorOf("albedo", {0.5, 1.2, 0.5});
    // A path of 100 mm takes red's coefficients far below the range (1/100 mm^-1 at most).
    const std::string far = errorOf("mfp", {100.0, 5.0, 5.0});
    EXPECT_NE(far.find("(from mfp) (red, mm^-1)"), std::string::npos) << far;
    EXPECT_NE(far.find("is outside the asset's editable range"), std::string::npos) << far;
    EXPECT_EQ(errorOf("albedo", {0.5}), "albedo takes 3 value(s), got 1");
}

}  // namespace
}  // namespace opal::view
