// Scene time in the viewer: a light moved by time samples, played and set from a script.
// Truths: at time code 24, halfway between samples at 0 and 48, the light is where linear
// interpolation puts it, and the viewer's picture is the one it shows of a still scene
// with the light there; playing advances time with the clock and loops over the layer's
// startTimeCode..endTimeCode; time is not an edit.
#include "delegate/render_delegate.h"
#include "examples/opal-view/core/viewer_model.h"
#include "tests/support/scene_usda.h"
#include "tests/view/exr_compare.h"

#include <gtest/gtest.h>

#include <iostream>

namespace opal::test {
namespace {

// The 5 mm sphere, a camera 30 mm away and a point light: still at (0, 5, 20), or moved
// by time samples from (-30, 5, 20) at time code 0 to (30, 5, 20) at 48 (24 per second).
std::string timeScene(bool animated) {
    using namespace usda;
    const std::string key = animated ? translateSamples({{0, {-30, 5, 20}}, {48, {30, 5, 20}}}) : translate({0, 5, 20});
    return header("    timeCodesPerSecond = 24\n    startTimeCode = 0\n    endTimeCode = 48\n") +
           reference("Sphere", "./sphere.usda") + pointLight("Key", "2000", key) + camera("Camera", translate({0, 0, 30}));
}

void expectLightAt(const view::ViewerModel& model, double x, const std::string& when) {
    const Imath::V3d at = view::lightPosition(model.light("/Key"));
    EXPECT_NEAR(at.x, x, 1e-9) << when;
    EXPECT_NEAR(at.y, 5.0, 1e-9) << when;
    EXPECT_NEAR(at.z, 20.0, 1e-9) << when;
}

TEST(SceneTime, SettingAndPlayingTimeMoveTheAnimatedLightWithoutAnEdit) {
    const SceneDir dir;
    dir.writeSphereAsset("sphere");
    OpalRenderDelegate delegate;
    view::ViewerModel model(delegate, 48, 32);
    model.open(dir.write("animated.usda", timeScene(true)));
    ASSERT_TRUE(model.animated());
    expectLightAt(model, -30.0, "opened at time code 0");
    model.setTime(12.0);
    expectLightAt(model, -15.0, "time code 12: a quarter of the way");
    EXPECT_EQ(model.title().find(" *"), std::string::npos) << "time is not an edit: " << model.title();
    model.advance(1.0);
    EXPECT_EQ(model.timeCode(), 12.0) << "paused: the clock does not move time";
    model.playing = true;
    model.advance(0.5);  // 12 time codes at 24 per second
    EXPECT_EQ(model.timeCode(), 24.0);
    expectLightAt(model, 0.0, "time code 24: halfway");
    model.advance(2.0);  // 24 + 48 = 72: past endTimeCode 48, looped to 24
    EXPECT_EQ(model.timeCode(), 24.0);
    EXPECT_THROW(model.setTime(std::numeric_limits<double>::quiet_NaN()), Error);

    model.open(dir.write("still.usda", timeScene(false)));
    EXPECT_FALSE(model.animated()) << "nothing in the still scene changes with time";
}

TEST(SceneTime, TheViewerAtTimeCode24ShowsTheStillSceneWithTheLightHalfway) {
    const SceneDir dir;
    dir.writeSphereAsset("sphere");
    const std::filesystem::path still = dir.write("still.usda", timeScene(false)),
                                animated = dir.write("animated.usda", timeScene(true));
    dir.write("time.script", "load " + scriptWord(still) + "\n" + saveExr(dir, "still.exr") + "load " +
                                 scriptWord(animated) + "\nplay\ntime 24\n" + saveExr(dir, "halfway.exr") +
                                 "time 0\n" + saveExr(dir, "start.exr") + "quit\n");
    const ViewRun run = runOpalView(dir, "--size 240x160 --script " + shellWord(dir / "time.script"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const ReadImage expected = readImage(dir / "still.exr"), halfway = readImage(dir / "halfway.exr"),
                    start = readImage(dir / "start.exr");
    const double largest = channelMean(expected, "subsurface.G");
    ASSERT_GT(largest, 0.0);
    const double difference = maxDifference(halfway, expected);
    std::cout << "time code 24 vs the still scene: EXR max difference " << difference << '\n';
    EXPECT_LE(difference, 1e-6 * largest) << "the light interpolated to where the still scene has it";
    EXPECT_GT(maxDifference(start, expected), 0.1 * largest) << "at time code 0 the light is elsewhere";
}

}  // namespace
}  // namespace opal::test
