// The camera's focal length, end to end: a sphere's image radius is f tan(asin(R / d)),
// linear in f, so halving the focal length quarters the pixels the framed sphere covers
// (within the rounding of its edge); a focal length out of range fails naming its line.
#include "tests/view/exr_compare.h"

#include <iostream>

namespace opal::test {
namespace {

int coveredPixels(const ReadImage& image) {
    const int a = image.channel("A");
    int covered = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) covered += image.at(x, y, a) > 0.5f;
    return covered;
}

TEST(Camera, HalvingTheFocalLengthQuartersTheSpheresImage) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    dir.write("lens.script", "load " + scriptWord(asset) + "\nsave exr " + scriptWord(dir / "long.exr") +
                                 "\ncamera focal 25\nsave exr " + scriptWord(dir / "short.exr") + "\nquit\n");
    const ViewRun run = runOpalView(dir, "--size 320x240 --script " + shellWord(dir / "lens.script"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const int longLens = coveredPixels(readImage(dir / "long.exr")), shortLens = coveredPixels(readImage(dir / "short.exr"));
    ASSERT_GT(shortLens, 500);
    std::cout << "covered pixels at 50 mm " << longLens << ", at 25 mm " << shortLens << '\n';
    EXPECT_NEAR(double(longLens) / shortLens, 4.0, 0.2);

    const std::filesystem::path bad = dir.write("bad.script", "load " + scriptWord(asset) + "\ncamera focal 0.5\n");
    const ViewRun refused = runOpalView(dir, "--size 160x120 --script " + shellWord(bad));
    EXPECT_EQ(refused.exitCode, 1);
    EXPECT_NE(refused.err.find(bad.string() + ":2: focal length 0.5"), std::string::npos) << refused.err;
}

}  // namespace
}  // namespace opal::test
