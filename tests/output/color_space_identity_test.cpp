#include "delegate/output/color_space_identity.h"

#include "schema/error.h"

#include <gtest/gtest.h>

#include <sstream>

namespace opal {
namespace {

// A minimal config whose scene_linear space "render space" is defined by `definition`
// (the transform lines of its ColorSpace entry), under a name no table knows.
OCIO::ConstConfigRcPtr configWithRenderSpace(const std::string& definition) {
    std::istringstream yaml(R"(ocio_profile_version: 2.1
roles:
  aces_interchange: ACES2065-1
  scene_linear: render space
  default: ACES2065-1
file_rules:
  - !<Rule> {name: Default, colorspace: default}
displays:
  sRGB:
    - !<View> {name: Raw, colorspace: Raw}
colorspaces:
  - !<ColorSpace>
    name: ACES2065-1
  - !<ColorSpace>
    name: Raw
    isdata: true
  - !<ColorSpace>
    name: render space
)" + definition + "\n");
    OCIO::ConstConfigRcPtr config = OCIO::Config::CreateFromStream(yaml);
    config->validate();
    return config;
}

TEST(ColorSpaceIdentity, NamesAndAliasesOfTheAcesConfigsAreKnown) {
    std::istringstream yaml(R"(ocio_profile_version: 2.1
roles:
  scene_linear: lin_srgb
  default: lin_srgb
file_rules:
  - !<Rule> {name: Default, colorspace: default}
displays:
  sRGB:
    - !<View> {name: Raw, colorspace: lin_srgb}
colorspaces:
  - !<ColorSpace>
    name: scene linear
    aliases: [lin_srgb]
)");
    const OCIO::ConstConfigRcPtr config = OCIO::Config::CreateFromStream(yaml);
    const ColorSpaceIdentity id = identifyColorSpace(*config, "lin_srgb", nullptr);
    EXPECT_EQ(id.name, "scene linear");
    EXPECT_EQ(id.interopId, "lin_rec709_scene");
    ASSERT_TRUE(id.chromaticities);
    EXPECT_DOUBLE_EQ(id.chromaticities->white.x, 0.3127);  // D65
}

TEST(ColorSpaceIdentity, Ap1IsRecognizedByOcioBuiltinMatrix) {
    // OCIO's own ACEScg -> ACES2065-1 builtin against the AP1/AP0 chromaticities in the
    // table: a match checks both.
    const OCIO::ConstConfigRcPtr config = configWithRenderSpace(
        "    to_scene_reference: !<BuiltinTransform> {style: ACEScg_to_ACES2065-1}");
    std::vector<std::string> warnings;
    const ColorSpaceIdentity id = identifyColorSpace(*config, "render space", &warnings);
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(id.interopId, "lin_ap1_scene");
    ASSERT_TRUE(id.chromaticities);
    EXPECT_DOUBLE_EQ(id.chromaticities->red.x, 0.713);
}

TEST(ColorSpaceIdentity, Rec709IsRecognizedByTheAcesConfigMatrix) {
    // The AP0 -> linear Rec.709 matrix of the ACES CG config (Bradford D60 -> D65).
    const OCIO::ConstConfigRcPtr config = configWithRenderSpace(
        "    from_scene_reference: !<MatrixTransform> {matrix: [2.52168618674388, "
        "-1.13413098823972, -0.387555198504164, 0, -0.276479914229922, 1.37271908766826, "
        "-0.096239173438334, 0, -0.0153780649660342, -0.152975335867399, 1.16835340083343, 0, "
        "0, 0, 0, 1]}");
    const ColorSpaceIdentity id = identifyColorSpace(*config, "render space", nullptr);
    EXPECT_EQ(id.interopId, "lin_rec709_scene");
    ASSERT_TRUE(id.chromaticities);
    EXPECT_DOUBLE_EQ(id.chromaticities->red.x, 0.64);
    EXPECT_DOUBLE_EQ(id.chromaticities->white.y, 0.3290);
}

TEST(ColorSpaceIdentity, UnknownLinearSpaceKeepsItsNameOnlyWithAWarning) {
    const OCIO::ConstConfigRcPtr config = configWithRenderSpace(
        "    to_scene_reference: !<MatrixTransform> {matrix: [2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, "
        "0, 0, 0, 1]}");
    std::vector<std::string> warnings;
    const ColorSpaceIdentity id = identifyColorSpace(*config, "render space", &warnings);
    EXPECT_EQ(id.name, "render space");
    EXPECT_FALSE(id.chromaticities);
    EXPECT_FALSE(id.interopId);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("'render space'"), std::string::npos) << warnings[0];
}

TEST(ColorSpaceIdentity, NonLinearSpaceHasNoChromaticities) {
    const OCIO::ConstConfigRcPtr config =
        configWithRenderSpace("    to_scene_reference: !<ExponentTransform> {value: 2.2}");
    std::vector<std::string> warnings;
    EXPECT_FALSE(identifyColorSpace(*config, "render space", &warnings).chromaticities);
    EXPECT_EQ(warnings.size(), 1u);
}

TEST(ColorSpaceIdentity, MissingColorSpaceIsAnError) {
    const OCIO::ConstConfigRcPtr config = configWithRenderSpace("");
    EXPECT_THROW(identifyColorSpace(*config, "ProPhoto", nullptr), Error);
}

}  // namespace
}  // namespace opal
