#include "delegate/output/display_transform.h"

#include "color_test_support.h"
#include "schema/error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace opal {
namespace {

// IEC 61966-2-1 sRGB encoding and decoding, written out (not taken from OCIO).
double srgbEncode(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}
double srgbDecode(double code) {
    return code <= 0.04045 ? code / 12.92 : std::pow((code + 0.055) / 1.055, 2.4);
}

float displayedGrey(const ColorConfig& config, const std::string& display,
                    const std::string& view) {
    Image grey(1, 1, 3);
    for (int c = 0; c < 3; ++c) grey.at(0, 0, c) = 0.18f;
    const Image shown = DisplayTransform(config, display, view).apply(grey);
    EXPECT_NEAR(shown.at(0, 0, 0), shown.at(0, 0, 1), 1e-5);  // neutral stays neutral
    EXPECT_NEAR(shown.at(0, 0, 2), shown.at(0, 0, 1), 1e-5);
    return shown.at(0, 0, 1);
}

TEST(DisplayTransform, UntoneMappedGreyIsTheSrgbEncodingOfMidGrey) {
    const ColorConfig config = ColorConfig::fromFile(test::shippedConfig());
    // ACEScg -> XYZ -> sRGB keeps a neutral at 0.18, then the sRGB curve: 0.4614.
    EXPECT_NEAR(displayedGrey(config, "sRGB - Display", "Un-tone-mapped"), srgbEncode(0.18), 1e-4);
    EXPECT_NEAR(displayedGrey(config, "Rec.1886 Rec.709 - Display", "Un-tone-mapped"),
                std::pow(0.18, 1.0 / 2.4), 1e-4);
}

TEST(DisplayTransform, AcesSdrShowsMidGreyAtAboutTenPercent) {
    // ACES 1.0: the RRT puts 0.18 at 4.8 of 48 cd/m^2 (0.1 of peak); the SDR video ODT
    // keeps that ratio and applies the dim-surround gamma 0.9811: 0.1^0.9811 = 0.1044.
    const ColorConfig config = ColorConfig::fromFile(test::shippedConfig());
    const double expected = std::pow(0.1, 0.9811);
    const float srgb = displayedGrey(config, "sRGB - Display", "ACES 1.0 - SDR Video");
    const float rec1886 =
        displayedGrey(config, "Rec.1886 Rec.709 - Display", "ACES 1.0 - SDR Video");
    EXPECT_NEAR(srgb, 0.356, 0.002);
    EXPECT_NEAR(srgbDecode(srgb), expected, 0.01 * expected);
    EXPECT_NEAR(std::pow(rec1886, 2.4), expected, 0.01 * expected);
}

TEST(DisplayTransform, MatchesOcioAppliedIndependentlyAndKeepsAlpha) {
    const ColorConfig config = ColorConfig::fromFile(test::shippedConfig());
    const Image scene = test::randomSceneLinear(67, 45, 4, 7, false);
    for (const char* view : {"ACES 1.0 - SDR Video", "Un-tone-mapped", "Raw"}) {
        const Image shown = DisplayTransform(config, "sRGB - Display", view).apply(scene);
        const Image expected = test::referenceDisplay(scene, "sRGB - Display", view);
        for (int y = 0; y < scene.height(); ++y) {
            for (int x = 0; x < scene.width(); ++x) {
                for (int c = 0; c < 3; ++c) {
                    ASSERT_NEAR(shown.at(x, y, c), expected.at(x, y, c), 1e-6)
                        << view << " " << x << "," << y;
                }
                ASSERT_EQ(shown.at(x, y, 3), scene.at(x, y, 3));
            }
        }
    }
}

TEST(DisplayTransform, RgbImagesWorkToo) {
    const ColorConfig config = ColorConfig::fromFile(test::shippedConfig());
    const Image scene = test::randomSceneLinear(20, 33, 3, 11, true);
    const Image shown = DisplayTransform(config).apply(scene);
    const Image expected = test::referenceDisplay(scene, "sRGB - Display", "ACES 1.0 - SDR Video");
    for (std::size_t i = 0; i < shown.pixels().size(); ++i) {
        ASSERT_NEAR(shown.pixels()[i], expected.pixels()[i], 1e-6) << i;
    }
}

TEST(DisplayTransform, RejectsImagesThatAreNotRgbOrRgba) {
    const ColorConfig config = ColorConfig::fromFile(test::shippedConfig());
    EXPECT_THROW(DisplayTransform(config).apply(Image(4, 4, 2)), Error);
}

TEST(DisplayTransform, UnknownViewIsAnError) {
    const ColorConfig config = ColorConfig::fromFile(test::shippedConfig());
    EXPECT_THROW(DisplayTransform(config, "sRGB - Display", "Filmic"), Error);
}

}  // namespace
}  // namespace opal
