// The display gamma, end to end: the saved PNG with gamma 2 holds, pixel for pixel, the
// square root of the one with gamma 1 (display-referred, after the view transform), within
// the 8-bit rounding of both, on the pixels the asset covers fully; a gamma that is not
// positive fails naming its line.
#include "tests/view/exr_compare.h"

namespace opal::test {
namespace {

TEST(DisplayGrade, GammaRaisesTheShownValuesToOneOverGamma) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    dir.write("gamma.script", "load " + scriptWord(asset) + "\nsave png " + scriptWord(dir / "one.png") +
                                  "\ngamma 2\nsave png " + scriptWord(dir / "two.png") + "\nquit\n");
    const ViewRun run = runOpalView(dir, "--size 160x120 --script " + shellWord(dir / "gamma.script"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const ReadImage one = readImage(dir / "one.png"), two = readImage(dir / "two.png");
    ASSERT_EQ(one.width, two.width);
    int compared = 0;
    double worst = 0.0;
    for (int y = 0; y < one.height; ++y)
        for (int x = 0; x < one.width; ++x)
            for (int c = 0; c < 3; ++c) {
                // Where the asset covers the pixel partly, the PNG's straight alpha is read
                // back premultiplied, which a power does not commute with.
                if (one.channels == 4 && one.at(x, y, 3) < 1.0f) continue;
                const double a = one.at(x, y, c);
                if (a < 16.0 / 255.0) continue;  // near 0 the square root magnifies the rounding
                worst = std::max(worst, std::abs(two.at(x, y, c) - std::sqrt(a)) * 255.0);
                ++compared;
            }
    EXPECT_GT(compared, 100);
    EXPECT_LE(worst, 1.5) << "codes";

    const std::filesystem::path bad = dir.write("bad.script", "load " + scriptWord(asset) + "\ngamma 0\n");
    const ViewRun refused = runOpalView(dir, "--size 160x120 --script " + shellWord(bad));
    EXPECT_EQ(refused.exitCode, 1);
    EXPECT_NE(refused.err.find(bad.string() + ":2: gamma 0"), std::string::npos) << refused.err;
}

}  // namespace
}  // namespace opal::test
