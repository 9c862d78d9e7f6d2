#include "delegate/output/preview_writer.h"

#include "color_test_support.h"
#include "delegate/output/display_transform.h"
#include "schema/error.h"

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

namespace opal {
namespace {

using test::TempDir;

struct Bytes {
    int width = 0, height = 0, channels = 0;
    std::vector<unsigned char> data;
    int at(int x, int y, int c) const {
        return data[(static_cast<std::size_t>(y) * width + x) * channels + c];
    }
};

// Reads the stored 8-bit codes as they are in the file (no alpha association on read).
Bytes readBytes(const std::filesystem::path& file) {
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(file.string(), &config);
    EXPECT_TRUE(in) << OIIO::geterror();
    Bytes b{in->spec().width, in->spec().height, in->spec().nchannels, {}};
    b.data.resize(static_cast<std::size_t>(b.width) * b.height * b.channels);
    EXPECT_TRUE(in->read_image(0, 0, 0, b.channels, OIIO::TypeDesc::UINT8, b.data.data()));
    return b;
}

TEST(PreviewWriter, QuantizesByRoundingAndClamping) {
    EXPECT_EQ(quantizeToByte(0.0f), 0);
    EXPECT_EQ(quantizeToByte(-0.5f), 0);
    EXPECT_EQ(quantizeToByte(std::nanf("")), 0);
    EXPECT_EQ(quantizeToByte(0.5f / 255.0f - 1e-6f), 0);
    EXPECT_EQ(quantizeToByte(0.5f / 255.0f + 1e-6f), 1);
    EXPECT_EQ(quantizeToByte(128.0f / 255.0f), 128);
    EXPECT_EQ(quantizeToByte(1.0f), 255);
    EXPECT_EQ(quantizeToByte(7.0f), 255);
}

TEST(PreviewWriter, PngPixelsMatchOcioAppliedIndependently) {
    TempDir dir;
    const ColorConfig config = ColorConfig::fromFile(test::shippedConfig());
    const Image scene = test::randomSceneLinear(53, 29, 4, 5, true);
    writePreview(dir / "preview.png", DisplayTransform(config).apply(scene));

    const Image expected = test::referenceDisplay(scene, "sRGB - Display", "ACES 1.0 - SDR Video");
    const Bytes png = readBytes(dir / "preview.png");
    ASSERT_EQ(png.width, 53);
    ASSERT_EQ(png.height, 29);
    ASSERT_EQ(png.channels, 4);
    for (int y = 0; y < png.height; ++y) {
        for (int x = 0; x < png.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double code = std::clamp(expected.at(x, y, c), 0.0f, 1.0f) * 255.0;
                ASSERT_LE(std::abs(png.at(x, y, c) - code), 1.0) << x << "," << y << "," << c;
            }
            ASSERT_EQ(png.at(x, y, 3), 255);
        }
    }
}

TEST(PreviewWriter, PngAlphaIsStoredUnassociated) {
    TempDir dir;
    Image shown(2, 1, 4);
    const float pixels[8] = {0.2f, 0.1f, 0.05f, 0.5f, 0.3f, 0.3f, 0.3f, 0.0f};
    std::copy(pixels, pixels + 8, shown.pixels().begin());
    writePreview(dir / "alpha.png", shown);
    const Bytes png = readBytes(dir / "alpha.png");
    EXPECT_EQ(png.at(0, 0, 0), 102);  // 0.2 / 0.5 = 0.4 -> 102
    EXPECT_EQ(png.at(0, 0, 1), 51);
    EXPECT_EQ(png.at(0, 0, 2), 26);
    EXPECT_EQ(png.at(0, 0, 3), 128);
    EXPECT_EQ(png.at(1, 0, 0), 0);  // fully transparent
    EXPECT_EQ(png.at(1, 0, 3), 0);
}

TEST(PreviewWriter, JpegIsRgb) {
    TempDir dir;
    Image shown(16, 8, 4);
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 16; ++x) {
            for (int c = 0; c < 3; ++c) shown.at(x, y, c) = 0.5f;
            shown.at(x, y, 3) = 1.0f;
        }
    }
    writePreview(dir / "preview.JPEG", shown);
    const Bytes jpeg = readBytes(dir / "preview.JPEG");
    EXPECT_EQ(jpeg.channels, 3);
    EXPECT_EQ(jpeg.width, 16);
    EXPECT_LE(std::abs(jpeg.at(5, 5, 1) - 128), 2);
}

TEST(PreviewWriter, UnknownExtensionIsRefusedAndNothingIsWritten) {
    TempDir dir;
    try {
        writePreview(dir / "preview.tif", Image(4, 4, 3));
        FAIL() << "expected an error";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("preview.tif"), std::string::npos) << message;
        EXPECT_NE(message.find("'.tif'"), std::string::npos) << message;
        EXPECT_NE(message.find(".png"), std::string::npos) << message;
    }
    EXPECT_TRUE(dir.entries().empty());
}

TEST(PreviewWriter, UnwritableDirectoryThrowsWithThePathAndLeavesNothing) {
    TempDir dir;
    std::ofstream(dir / "file") << "x";
    const std::filesystem::path target = dir / "file/preview.png";
    try {
        writePreview(target, Image(4, 4, 3));
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
    }
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"file"});
}

}  // namespace
}  // namespace opal
