// The optional panels, on screen: the keyboard help (H) covers the middle of the window with
// its table; without it the same converged picture shows there.
#include "tests/view/view_process.h"

#include <iostream>

namespace opal::test {
namespace {

// The fraction of pixels in the box (x0, y0)-(x1, y1) whose colour differs.
double changedFraction(const ReadImage& a, const ReadImage& b, int x0, int y0, int x1, int y1) {
    int changed = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            for (int c = 0; c < 3; ++c)
                if (a.at(x, y, c) != b.at(x, y, c)) {
                    ++changed;
                    break;
                }
    return double(changed) / ((x1 - x0) * (y1 - y0));
}

TEST(Panels, TheKeyboardHelpCoversTheMiddleOfTheWindow) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    dir.write("help.script", "load " + scriptWord(asset) + "\nwait\nscreenshot " + scriptWord(dir / "plain.png") +
                                 "\npanel help on\nwait\nscreenshot " + scriptWord(dir / "help.png") + "\nquit\n");
    const ViewRun run = runOpalView(dir, "--size 960x540 --script " + shellWord(dir / "help.script"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const ReadImage plain = readImage(dir / "plain.png"), help = readImage(dir / "help.png");
    // The help table, centred: wider than 500 and taller than 150 pixels at ImGui's font.
    const double middle = changedFraction(plain, help, 230, 195, 730, 345);
    const double corner = changedFraction(plain, help, 900, 60, 960, 120);
    std::cout << "help on: " << middle * 100 << "% of the middle changed, " << corner * 100 << "% of a corner\n";
    EXPECT_GT(middle, 0.5);
    EXPECT_EQ(corner, 0.0);

    const std::filesystem::path bad = dir.write("bad.script", "load " + scriptWord(asset) + "\npanel toolbox on\n");
    const ViewRun refused = runOpalView(dir, "--size 160x120 --script " + shellWord(bad));
    EXPECT_EQ(refused.exitCode, 1);
    EXPECT_NE(refused.err.find(bad.string() + ":2: unknown panel 'toolbox'"), std::string::npos) << refused.err;
}

}  // namespace
}  // namespace opal::test
