// The A/B wipe, end to end: left of its line the window shows the engine's picture, right of
// it the exact reference's (opal:reference). Truths: the window's pixels with the wipe on
// match, left of the line, a screenshot of the engine alone and, right of it, one of the
// reference alone (both converged, the renderer is deterministic), on a sphere whose
// transfer is compressed hard, so that the two renders differ measurably. The screenshots
// hold the interface too: the regions compared lie right of the panel, below the menu and
// above the heads-up line.
#include "tests/view/exr_compare.h"

#include <iostream>

namespace opal::test {
namespace {

constexpr int WindowWidth = 800, WindowHeight = 320;
constexpr double Split = 0.6;  // the line at column 480

// The 5 mm sphere with a lossy transfer (2% of its wavelet coefficients kept, as a hard
// compression would), so that the engine's picture departs from the exact gather's.
std::filesystem::path writeLossySphere(const SceneDir& dir) {
    auto asset = std::make_shared<TranslucentAsset>(*sphereAsset(2, 5.0f, 0));
    buildTransfer(*asset, 0.02, 0.5);
    asset->bake.identifier = 0x5e1f0b5e55ed0003ull;
    writeSidecar(dir / "lossy.opal", *asset);
    writeAssetLayer(dir / "lossy.usda", *asset, "./lossy.opal");
    return dir / "lossy.usda";
}

// The largest |a - b| over the colour channels of the columns [x0, x1) and rows [y0, y1).
double maxDifferenceIn(const ReadImage& a, const ReadImage& b, int x0, int x1, int y0, int y1) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    double worst = 0.0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(double(a.at(x, y, c)) - double(b.at(x, y, c))));
    return worst;
}

TEST(Wipe, TheEngineShowsLeftOfTheLineAndTheReferenceRightOfIt) {
    const SceneDir dir;
    const std::filesystem::path asset = writeLossySphere(dir);
    const auto shot = [&](const std::string& name) { return "wait\nscreenshot " + scriptWord(dir / name) + "\n"; };
    dir.write("wipe.script", "load " + scriptWord(asset) + "\n" + shot("engine.png") + "setting opal:reference true\n" +
                                 shot("reference.png") + "setting opal:reference false\nwipe " + std::to_string(Split) +
                                 "\n" + shot("wipe.png") + "wipe off\n" + shot("off.png") + "quit\n");
    const ViewRun run = runOpalView(dir, "--size " + std::to_string(WindowWidth) + "x" + std::to_string(WindowHeight) +
                                             " --script " + shellWord(dir / "wipe.script"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const ReadImage engine = readImage(dir / "engine.png"), reference = readImage(dir / "reference.png"),
                    wipe = readImage(dir / "wipe.png"), off = readImage(dir / "off.png");
    // The sphere spans columns 240 to 560; the panel ends at 310, the line is at 480.
    const int top = 40, bottom = 230, line = int(Split * WindowWidth);
    const int leftFrom = 330, leftTo = line - 6, rightFrom = line + 6, rightTo = 555;
    const double leftApart = maxDifferenceIn(engine, reference, leftFrom, leftTo, top, bottom),
                 rightApart = maxDifferenceIn(engine, reference, rightFrom, rightTo, top, bottom);
    const double leftEngine = maxDifferenceIn(wipe, engine, leftFrom, leftTo, top, bottom),
                 rightReference = maxDifferenceIn(wipe, reference, rightFrom, rightTo, top, bottom);
    std::cout << "engine vs reference: " << leftApart * 255.0 << " codes left of the line, " << rightApart * 255.0
              << " right; the wipe vs the engine on the left " << leftEngine * 255.0 << ", vs the reference on the right "
              << rightReference * 255.0 << '\n';
    ASSERT_GT(leftApart, 4.0 / 255.0) << "the two renders must differ for the test to tell them apart";
    ASSERT_GT(rightApart, 4.0 / 255.0);
    EXPECT_LE(leftEngine, 1.0 / 255.0);
    EXPECT_LE(rightReference, 1.0 / 255.0);
    EXPECT_LE(maxDifferenceIn(off, engine, leftFrom, rightTo, top, bottom), 1.0 / 255.0) << "wipe off: the engine alone";
}

TEST(Wipe, ALinePlacedOutsideTheWindowFailsWithItsLine) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    const std::filesystem::path bad = dir.write("bad.script", "load " + scriptWord(asset) + "\nwipe 1.5\n");
    const ViewRun run = runOpalView(dir, "--size 160x120 --script " + shellWord(bad));
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.err.find("bad.script:2: wipe 1.5"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace opal::test
