// opal-view end to end, as a person or a pipeline runs it: a small baked asset on disk, the
// viewer started as a process on the X display (Mesa's software OpenGL under xvfb-run),
// driven by --screenshot and --script. What it saves is measured against what the edit
// must do physically: the asset appears where the camera looks; absorbing more red and
// blue leaves it greener; a light moved from left to right moves the bright side with it.
// A bad script fails with its line.
#include "tests/view/exr_compare.h"
#include "tests/support/scene_usda.h"

#include <cmath>
#include <iostream>

namespace opal::test {
namespace {

// The 5 mm sphere placed at x = 40, a light, and a camera 30 mm in front of it and 3 mm to
// its left (looking down -Z), so the sphere lies right of the picture's centre.
std::string offsetScene() {
    using namespace usda;
    return header() + reference("Sphere", "./sphere.usda", translate({40, 0, 0})) +
           pointLight("Bulb", "2000", translate({40, 5, 20})) + camera("Camera", translate({37, 0, 30}));
}

// The mean of a square of pixels' brightest channel.
double blockLevel(const ReadImage& image, int cx, int cy, int half) {
    double sum = 0.0;
    int count = 0;
    for (int y = cy - half; y <= cy + half; ++y)
        for (int x = cx - half; x <= cx + half; ++x, ++count)
            sum += std::max({image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)});
    return sum / count;
}

// Over the asset's pixels (alpha 1 in the EXR's default layer): mean g / (r + g + b).
double meanGreenness(const ReadImage& exr) {
    const int r = exr.channel("R"), g = exr.channel("G"), b = exr.channel("B"), a = exr.channel("A");
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y < exr.height; ++y)
        for (int x = 0; x < exr.width; ++x) {
            const double total = exr.at(x, y, r) + exr.at(x, y, g) + exr.at(x, y, b);
            if (exr.at(x, y, a) < 0.999f || total <= 0.0) continue;
            sum += exr.at(x, y, g) / total;
            ++count;
        }
    EXPECT_GT(count, 1000) << "the asset covers too few pixels";
    return sum / std::max(count, 1);
}

TEST(Viewer, TheScreenshotShowsTheAssetWhereTheSceneCameraLooks) {
    const SceneDir dir;
    dir.writeSphereAsset("sphere");
    dir.write("scene.usda", offsetScene());
    const ViewRun run = runOpalView(dir, "'" + (dir / "scene.usda").string() + "' --size 960x540 --screenshot '" +
                                             (dir / "shot.png").string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const ReadImage shot = readImage(dir / "shot.png");
    ASSERT_EQ(shot.width, 960);
    ASSERT_EQ(shot.height, 540);
    // The 36 x 24 mm film fitted into 960 x 540 (as opal-render fits it) shows 24 mm over
    // 540 pixels: the sphere's centre, 3 mm off the view axis at 30 mm, lies
    // 3 / 30 x 50 mm = 112 pixels right of the centre, its radius (5 mm at 30) about 190
    // pixels. Left and right of it the empty background (no dome: black), where no panel
    // lies. Framing the sphere instead of looking through the scene's camera would centre it.
    EXPECT_GT(blockLevel(shot, 592, 270, 4), 0.15);
    EXPECT_LT(blockLevel(shot, 350, 270, 4), 0.02);
    EXPECT_LT(blockLevel(shot, 900, 270, 4), 0.02);
}

TEST(Viewer, RaisingRedAndBlueAbsorptionMakesTheAssetGreener) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    // The sphere's default sigma_a is (0.05, 0.1, 0.2) mm^-1, its range up to 0.3.
    dir.write("look.script", "load " + asset.string() + "\nwait\nsave exr " + (dir / "before.exr").string() +
                                 "\nmaterial set sigma_a 0.3 0.1 0.3\nwait\nsave exr " + (dir / "after.exr").string() +
                                 "\nquit\n");
    const ViewRun run = runOpalView(dir, "--size 480x320 --script '" + (dir / "look.script").string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const double before = meanGreenness(readImage(dir / "before.exr"));
    const double after = meanGreenness(readImage(dir / "after.exr"));
    std::cout << "greenness before " << before << ", after " << after << '\n';
    EXPECT_GT(after, before + 0.02);
}

TEST(Viewer, MovingThePointLightFromLeftToRightMovesTheBrightSide) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    dir.write("light.script", "load " + asset.string() + "\nlight move /_OpalView/KeyLight -30 0 15\nsave exr " +
                                  (dir / "left.exr").string() + "\nlight move /_OpalView/KeyLight 30 0 15\nsave exr " +
                                  (dir / "right.exr").string() + "\nquit\n");
    const ViewRun run = runOpalView(dir, "--size 480x320 --script '" + (dir / "light.script").string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const double left = brightSide(readImage(dir / "left.exr"));
    const double right = brightSide(readImage(dir / "right.exr"));
    std::cout << "bright side lit from the left " << left << " px, from the right " << right << " px\n";
    EXPECT_LT(left, -5.0) << "lit from the left: bright side at " << left << " pixels";
    EXPECT_GT(right, 5.0) << "lit from the right: bright side at " << right << " pixels";
}

// The picture is shown through the delegate's OCIO config: a scene's opal:ocioConfig (here
// Opal's config with its sRGB display renamed) replaces $OCIO's or the shipped one.
TEST(Viewer, ShowsThePictureThroughTheScenesOcioConfig) {
    const SceneDir dir;
    dir.writeSphereAsset("sphere");
    std::string config = slurpFile(std::filesystem::path(OPAL_SOURCE_DIR) / "delegate/output/ocio/config.ocio");
    for (std::size_t at; (at = config.find("sRGB - Display")) != std::string::npos;) config.replace(at, 14, "Test sRGB");
    dir.write("renamed.ocio", config);
    const std::string scene = offsetScene() + R"(
def RenderSettings "Settings"
{
    asset opal:ocioConfig = @./renamed.ocio@
}
)";
    dir.write("with-config.usda", scene);
    dir.write("without-config.usda", offsetScene());
    const std::filesystem::path script = dir.write("view.script", "view \"Test sRGB\" \"ACES 1.0 - SDR Video\"\nquit\n");
    const ViewRun with = runOpalView(dir, "'" + (dir / "with-config.usda").string() + "' --script '" + script.string() + "'");
    EXPECT_EQ(with.exitCode, 0) << with.err;
    const ViewRun without =
        runOpalView(dir, "'" + (dir / "without-config.usda").string() + "' --script '" + script.string() + "'");
    EXPECT_EQ(without.exitCode, 1);
    EXPECT_NE(without.err.find(script.string() + ":1: "), std::string::npos) << without.err;
}

TEST(Viewer, AScriptWithABadActionFailsWithItsLine) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    const std::filesystem::path syntax = dir.write("syntax.script", "load " + asset.string() + "\nwait\nmaterial set sigma_q 1 2 3\n");
    const ViewRun bad = runOpalView(dir, "--script '" + syntax.string() + "'");
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.err.find(syntax.string() + ":3: bad arguments for 'material'"), std::string::npos) << bad.err;

    // Parsed, but wrong for this scene: found when the action runs.
    const std::filesystem::path scene =
        dir.write("scene.script", "load " + asset.string() + "\nmaterial set sigma_a 0.1 0.1 0.1\nlight move /Nope 0 0 0\nquit\n");
    const ViewRun missing = runOpalView(dir, "--script '" + scene.string() + "'");
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.err.find(scene.string() + ":3: no light </Nope>"), std::string::npos) << missing.err;

    const std::filesystem::path range =
        dir.write("range.script", "load " + asset.string() + "\nmaterial set sigma_a 0.1 0.1 5\n");
    const ViewRun outside = runOpalView(dir, "--script '" + range.string() + "'");
    EXPECT_EQ(outside.exitCode, 1);
    EXPECT_NE(outside.err.find(range.string() + ":2: sigma_a (blue, mm^-1) 5 is outside the asset's editable range"),
              std::string::npos)
        << outside.err;
}

}  // namespace
}  // namespace opal::test
