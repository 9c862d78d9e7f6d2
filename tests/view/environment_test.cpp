// The environment panel's edits, end to end through scripts: a dome with a half-bright
// lat-long image, turned about the up axis. Truths: turning it 90 degrees twice gives the
// picture of one 180-degree turn; the turned dome, saved, renders in opal-render as the
// viewer shows it; the background switch hides the dome from the camera only, and the
// saved layer keeps it.
#include "tests/view/exr_compare.h"

#include <OpenImageIO/imageio.h>

#include <iostream>

namespace opal::test {
namespace {

// 64 x 32 lat-long, radiance 4 on the left half of the image, 0.1 on the right.
void writeHalfBrightSky(const std::filesystem::path& file) {
    const int width = 64, height = 32;
    std::vector<float> pixels(std::size_t(width) * height * 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) pixels[(std::size_t(y) * width + x) * 3 + c] = x < width / 2 ? 4.0f : 0.1f;
    auto out = OIIO::ImageOutput::create(file.string());
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(file.string(), OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
    out->close();
}


TEST(Environment, TurningTheDomeRelightsTheAssetAsTheSavedSceneRendersIt) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere", true);
    writeHalfBrightSky(dir / "sky.exr");
    dir.write("turn.script", "load " + scriptWord(asset) + "\nlight disable /_OpalView/KeyLight\nlight add dome\n" +
                                 "environment texture " + scriptWord(dir / "sky.exr") + "\n" + saveExr(dir, "still.exr") +
                                 "environment rotate 90\nenvironment rotate 90\n" + saveExr(dir, "twice.exr") +
                                 "environment rotate -180\nenvironment rotate 180\n" + saveExr(dir, "viewer.exr") +
                                 "save usda " + scriptWord(dir / "saved.usda") + "\nenvironment background off\n" +
                                 saveExr(dir, "hidden.exr") + "save usda " + scriptWord(dir / "hidden.usda") + "\nquit\n");
    const ViewRun run = runOpalView(dir, "--size 320x240 --script " + shellWord(dir / "turn.script"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const ReadImage still = readImage(dir / "still.exr"), twice = readImage(dir / "twice.exr"),
                    once = readImage(dir / "viewer.exr"), hidden = readImage(dir / "hidden.exr");
    const double largest = channelMean(still, "subsurface.G") + channelMean(once, "subsurface.G");
    ASSERT_GT(largest, 0.0);
    EXPECT_LE(maxDifference(twice, once), 1e-4 * largest) << "two turns of 90 degrees are one of 180";
    EXPECT_GT(maxDifference(still, once), 0.1 * largest) << "the half-bright dome turned: the asset is lit otherwise";

    const ViewRun render = runOpalRender(dir, shellWord(dir / "saved.usda") + " -o " + shellWord(dir / "render.exr"));
    ASSERT_EQ(render.exitCode, 0) << render.err;
    const double difference = maxDifference(once, readImage(dir / "render.exr"));
    std::cout << "turned dome, viewer vs opal-render on the saved layer: EXR max difference " << difference << '\n';
    EXPECT_LE(difference, 1e-5);

    // A corner sees only the dome: with the background off its colour and alpha are 0,
    // while the asset's own light is unchanged.
    const int r = once.channel("R"), a = once.channel("A");
    EXPECT_GT(once.at(0, 0, r), 0.0f);
    EXPECT_EQ(hidden.at(0, 0, r), 0.0f);
    EXPECT_EQ(hidden.at(0, 0, a), 0.0f);
    EXPECT_DOUBLE_EQ(channelMean(hidden, "subsurface.G"), channelMean(once, "subsurface.G"));

    // The switch is saved: opal-render leaves the background out as the viewer did.
    const ViewRun hiddenRender = runOpalRender(dir, shellWord(dir / "hidden.usda") + " -o " + shellWord(dir / "hidden-render.exr"));
    ASSERT_EQ(hiddenRender.exitCode, 0) << hiddenRender.err;
    const double hiddenDifference = maxDifference(hidden, readImage(dir / "hidden-render.exr"));
    std::cout << "background hidden, viewer vs opal-render on the saved layer: EXR max difference " << hiddenDifference << '\n';
    EXPECT_LE(hiddenDifference, 1e-5);
}

TEST(Environment, WithoutADomeOrWithAMissingImageTheScriptFailsWithItsLine) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    const std::filesystem::path none = dir.write("none.script", "load " + scriptWord(asset) + "\nenvironment rotate 10\n");
    const ViewRun noDome = runOpalView(dir, "--size 160x120 --script " + shellWord(none));
    EXPECT_EQ(noDome.exitCode, 1);
    EXPECT_NE(noDome.err.find(none.string() + ":2: the scene has no dome light"), std::string::npos) << noDome.err;
    const std::filesystem::path missing = dir.write(
        "missing.script", "load " + scriptWord(asset) + "\nlight add dome\nenvironment texture " +
                              scriptWord(dir / "nowhere.exr") + "\n");
    const ViewRun noImage = runOpalView(dir, "--size 160x120 --script " + shellWord(missing));
    EXPECT_EQ(noImage.exitCode, 1);
    EXPECT_NE(noImage.err.find(missing.string() + ":3: " + (dir / "nowhere.exr").string() + ": no such image"),
              std::string::npos)
        << noImage.err;
}

}  // namespace
}  // namespace opal::test
