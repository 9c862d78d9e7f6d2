// `opal-bench compare` reads the layers of opal-render's EXRs (bench/exr_layer.h): a file
// written here with known values in every channel reads back as the layer asked for, and
// the mask keeps only the pixels both images give the chosen prim.
#include "bench/exr_layer.h"
#include "schema/error.h"

#include "tests/support/open_temp_dir.h"

#include <gtest/gtest.h>
#include <OpenImageIO/imageio.h>

#include <string>
#include <vector>

namespace opal::bench {
namespace {

// A 3 x 1 opal-render-like EXR: color R/G/B, subsurface.R/G/B and primId.id, every value
// distinct: pixel p, channel c holds 10 p + c (primId: the given ids).
void writeExr(const std::filesystem::path& path, const std::vector<float>& ids) {
    OIIO::ImageSpec spec(3, 1, 7, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"B", "G", "R", "primId.id", "subsurface.B", "subsurface.G", "subsurface.R"};
    std::vector<float> px(3 * 7);
    for (int p = 0; p < 3; ++p)
        for (int c = 0; c < 7; ++c) px[p * 7 + c] = c == 3 ? ids[p] : float(10 * p + c);
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out && out->open(path.string(), spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
    out->close();
}

TEST(ExrLayer, ReadsTheLayersChannelsInRgbOrder) {
    const test::OpenTempDir dir;
    writeExr(dir / "a.exr", {0.0f, 1.0f, -1.0f});
    const ExrLayer sub = readExrLayer((dir / "a.exr").string(), "subsurface");
    ASSERT_EQ(sub.width, 3);
    ASSERT_EQ(sub.height, 1);
    EXPECT_EQ(sub.rgb, (std::vector<float>{6, 5, 4, 16, 15, 14, 26, 25, 24}));
    EXPECT_EQ(sub.primId, (std::vector<float>{0, 1, -1}));
    const ExrLayer color = readExrLayer((dir / "a.exr").string(), "color");
    EXPECT_EQ(color.rgb, (std::vector<float>{2, 1, 0, 12, 11, 10, 22, 21, 20}));
}

TEST(ExrLayer, TheMaskKeepsThePixelsBothImagesGiveTheChosenPrims) {
    const test::OpenTempDir dir;
    writeExr(dir / "a.exr", {0.0f, 1.0f, 0.0f});
    writeExr(dir / "b.exr", {0.0f, 1.0f, 1.0f});
    const ExrLayer a = readExrLayer((dir / "a.exr").string(), "subsurface"),
                   b = readExrLayer((dir / "b.exr").string(), "subsurface");
    EXPECT_EQ(primMask(a, b, {0}), (std::vector<std::uint8_t>{1, 0, 0}));
    EXPECT_EQ(primMask(a, b, {0, 1}), (std::vector<std::uint8_t>{1, 1, 0}));
    ExrLayer transposed = b;
    transposed.width = 1;
    transposed.height = 3;
    try {
        (void)primMask(a, transposed, {0});
        FAIL() << "images of other sizes were compared";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("b.exr: 1x3, but "), std::string::npos) << e.what();
    }
}

TEST(ExrLayer, AMissingLayerOrFileIsNamed) {
    const test::OpenTempDir dir;
    writeExr(dir / "a.exr", {0.0f, 0.0f, 0.0f});
    try {
        (void)readExrLayer((dir / "a.exr").string(), "specular");
        FAIL() << "a missing layer was read";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("a.exr: no channel specular.R"), std::string::npos) << e.what();
    }
    EXPECT_THROW((void)readExrLayer((dir / "none.exr").string(), "subsurface"), Error);
}

}  // namespace
}  // namespace opal::bench
