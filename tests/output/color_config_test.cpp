#include "delegate/output/color_config.h"

#include "color_test_support.h"
#include "schema/error.h"

#include <gtest/gtest.h>

#include <array>
#include <fstream>

namespace opal {
namespace {

using test::TempDir;

std::optional<std::string> unset(const char*) { return std::nullopt; }

ColorConfig::EnvironmentLookup ocioIs(std::string value) {
    return [value](const char* name) -> std::optional<std::string> {
        if (std::string(name) == "OCIO") return value;
        return std::nullopt;
    };
}

std::string messageOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(ColorConfig, ShippedConfigLoadsAndValidates) {
    const ColorConfig config = ColorConfig::fromFile(test::shippedConfig());
    EXPECT_NO_THROW(config.ocio()->validate());  // what ociocheck runs
    EXPECT_EQ(config.workingSpace(), "ACEScg");
    EXPECT_EQ(std::string(config.ocio()->getColorSpace("aces_interchange")->getName()),
              "ACES2065-1");
    EXPECT_EQ(std::string(config.ocio()->getColorSpace("data")->getName()), "Raw");
    EXPECT_EQ(std::string(config.ocio()->getColorSpace("color_picking")->getName()),
              "sRGB - Texture");
    EXPECT_EQ(config.displays(),
              (std::vector<std::string>{"sRGB - Display", "Rec.1886 Rec.709 - Display"}));
    for (const std::string& display : config.displays()) {
        EXPECT_EQ(config.views(display),
                  (std::vector<std::string>{"ACES 1.0 - SDR Video", "Un-tone-mapped", "Raw"}));
    }
    EXPECT_EQ(config.defaultDisplay(), "sRGB - Display");
    EXPECT_EQ(config.defaultView("sRGB - Display"), "ACES 1.0 - SDR Video");
}

TEST(ColorConfig, ShippedConfigNeedsNoFiles) {
    // No LUTs: every transform is a builtin or a matrix, so the config works from anywhere.
    const ColorConfig config = ColorConfig::fromFile(test::shippedConfig());
    for (int i = 0; i < config.ocio()->getNumColorSpaces(); ++i) {
        const char* name = config.ocio()->getColorSpaceNameByIndex(i);
        EXPECT_NO_THROW(config.ocio()->getProcessor(name, "ACES2065-1")) << name;
    }
    EXPECT_STREQ(config.ocio()->getSearchPath(), "");
}

TEST(ColorConfig, WorkingSpaceIdentityIsAp1) {
    std::vector<std::string> warnings;
    const ColorSpaceIdentity id =
        ColorConfig::fromFile(test::shippedConfig()).workingSpaceIdentity(&warnings);
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(id.name, "ACEScg");
    EXPECT_EQ(id.interopId, "lin_ap1_scene");
    ASSERT_TRUE(id.chromaticities);
    // Academy S-2014-004 (ACEScg): AP1 primaries, ACES white.
    EXPECT_DOUBLE_EQ(id.chromaticities->red.x, 0.713);
    EXPECT_DOUBLE_EQ(id.chromaticities->red.y, 0.293);
    EXPECT_DOUBLE_EQ(id.chromaticities->green.x, 0.165);
    EXPECT_DOUBLE_EQ(id.chromaticities->green.y, 0.830);
    EXPECT_DOUBLE_EQ(id.chromaticities->blue.x, 0.128);
    EXPECT_DOUBLE_EQ(id.chromaticities->blue.y, 0.044);
    EXPECT_DOUBLE_EQ(id.chromaticities->white.x, 0.32168);
    EXPECT_DOUBLE_EQ(id.chromaticities->white.y, 0.33767);
}

TEST(ColorConfig, EnvironmentMapsConvertFromLinearRec709) {
    const ColorConfig config = ColorConfig::fromFile(test::shippedConfig());
    const OCIO::ConstCPUProcessorRcPtr cpu =
        config.toWorking(std::string(kEnvironmentMapColorSpace))->getDefaultCPUProcessor();
    // The published linear sRGB -> ACEScg matrix (Bradford D65 -> ACES white), by columns.
    const std::array<std::array<float, 3>, 3> expectedColumns = {{
        {0.6130974f, 0.0701937f, 0.0206156f},
        {0.3395231f, 0.9163539f, 0.1095698f},
        {0.0473795f, 0.0134524f, 0.8698147f},
    }};
    for (int c = 0; c < 3; ++c) {
        std::array<float, 3> rgb{0, 0, 0};
        rgb[c] = 1.0f;
        cpu->applyRGB(rgb.data());
        for (int r = 0; r < 3; ++r) EXPECT_NEAR(rgb[r], expectedColumns[c][r], 2e-4) << c << r;
    }
}

TEST(ColorConfig, UnknownDisplayListsTheAvailableOnes) {
    const ColorConfig config = ColorConfig::fromFile(test::shippedConfig());
    const std::string message = messageOf([&] { config.workingToDisplay("P3 Monitor", "Raw"); });
    EXPECT_NE(message.find(test::shippedConfig().string()), std::string::npos) << message;
    EXPECT_NE(message.find("no display 'P3 Monitor'"), std::string::npos) << message;
    EXPECT_NE(message.find("'sRGB - Display', 'Rec.1886 Rec.709 - Display'"), std::string::npos)
        << message;
}

TEST(ColorConfig, UnknownViewListsTheAvailableOnes) {
    const ColorConfig config = ColorConfig::fromFile(test::shippedConfig());
    const std::string message =
        messageOf([&] { config.workingToDisplay("sRGB - Display", "Filmic"); });
    EXPECT_NE(message.find("display 'sRGB - Display' has no view 'Filmic'"), std::string::npos)
        << message;
    EXPECT_NE(message.find("'ACES 1.0 - SDR Video', 'Un-tone-mapped', 'Raw'"), std::string::npos)
        << message;
}

TEST(ColorConfig, UnknownInputColorSpaceIsAnError) {
    const ColorConfig config = ColorConfig::fromFile(test::shippedConfig());
    const std::string message = messageOf([&] { config.toWorking("Linear ProPhoto"); });
    EXPECT_NE(message.find("no color space, alias or role 'Linear ProPhoto'"), std::string::npos)
        << message;
}

TEST(ColorConfig, WithoutOcioTheShippedConfigIsUsed) {
    const ColorConfig config = ColorConfig::fromEnvironment(unset, "/nonexistent/bin/opal-render");
    EXPECT_TRUE(std::filesystem::equivalent(config.file(), test::shippedConfig()));
    const ColorConfig empty =
        ColorConfig::fromEnvironment(ocioIs(""), "/nonexistent/bin/opal-render");
    EXPECT_TRUE(std::filesystem::equivalent(empty.file(), test::shippedConfig()));
}

TEST(ColorConfig, InstalledConfigNextToTheExecutableComesFirst) {
    EXPECT_EQ(ColorConfig::shippedConfigCandidates("/opt/opal/bin/opal-render").front(),
              std::filesystem::path("/opt/opal/share/opal/ocio/config.ocio"));

    TempDir prefix;
    std::filesystem::create_directories(prefix / "share/opal/ocio");
    std::filesystem::create_directories(prefix / "bin");
    std::filesystem::copy_file(test::shippedConfig(), prefix / "share/opal/ocio/config.ocio");
    const ColorConfig config = ColorConfig::fromEnvironment(unset, prefix / "bin/opal-view");
    EXPECT_EQ(config.file(), prefix / "share/opal/ocio/config.ocio");
}

TEST(ColorConfig, OcioPointingAtTheStudioConfigWorks) {
    if (!std::filesystem::exists(test::studioConfig())) GTEST_SKIP() << "no ../shared assets";
    const ColorConfig config = ColorConfig::fromEnvironment(ocioIs(test::studioConfig().string()),
                                                            "/nonexistent/bin/opal");
    EXPECT_EQ(config.file(), test::studioConfig());
    EXPECT_EQ(config.workingSpace(), "ACEScg");
    EXPECT_EQ(config.defaultDisplay(), "sRGB - Display");
    EXPECT_EQ(config.defaultView("sRGB - Display"), "ACES 1.0 - SDR Video");
    EXPECT_NO_THROW(config.workingToDisplay("Rec.1886 Rec.709 - Display", "Un-tone-mapped"));
    EXPECT_NO_THROW(config.toWorking(std::string(kEnvironmentMapColorSpace)));
    const ColorSpaceIdentity id = config.workingSpaceIdentity(nullptr);
    EXPECT_EQ(id.interopId, "lin_ap1_scene");
    EXPECT_TRUE(id.chromaticities);
}

TEST(ColorConfig, OcioThatDoesNotLoadIsAnErrorNotAFallback) {
    const std::string message = messageOf([] {
        ColorConfig::fromEnvironment(ocioIs("/nowhere/studio.ocio"), "/nonexistent/bin/opal");
    });
    EXPECT_NE(message.find("$OCIO"), std::string::npos) << message;
    EXPECT_NE(message.find("/nowhere/studio.ocio"), std::string::npos) << message;
}

TEST(ColorConfig, MalformedConfigNamesTheFile) {
    TempDir dir;
    const std::filesystem::path file = dir / "broken.ocio";
    std::ofstream(file) << "ocio_profile_version: 2.1\nroles: [this is not a map\n";
    const std::string message = messageOf([&] { ColorConfig::fromFile(file); });
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
}

TEST(ColorConfig, ConfigWithoutSceneLinearRoleIsRejected) {
    TempDir dir;
    const std::filesystem::path file = dir / "no_scene_linear.ocio";
    std::ofstream(file) << R"(ocio_profile_version: 2.1
roles:
  default: Raw
file_rules:
  - !<Rule> {name: Default, colorspace: default}
displays:
  sRGB:
    - !<View> {name: Raw, colorspace: Raw}
colorspaces:
  - !<ColorSpace>
    name: Raw
    isdata: true
)";
    const std::string message = messageOf([&] { ColorConfig::fromFile(file); });
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
    EXPECT_NE(message.find("scene_linear"), std::string::npos) << message;
}

}  // namespace
}  // namespace opal
