// Which camera the viewer looks through and what it frames, end to end. Truths from the
// geometry of a pinhole camera: a sphere framed by "frame selection" just fills the smaller
// side of the picture, centred; a camera at x = c, 150 mm from two spheres placed
// symmetrically about the origin, images their mean at x = W/2 (1 - c / 150 * f / 18)
// (film 36 mm wide); a field of view of 2 atan(18 / f) degrees is the lens of focal
// length f (the sphere's image scales with f, its area with f squared); a far plane
// nearer than the sphere leaves nothing to see.
#include "delegate/render_delegate.h"
#include "examples/opal-view/core/viewer_model.h"
#include "tests/view/exr_compare.h"
#include "tests/support/scene_usda.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

namespace opal::test {
namespace {

constexpr int Width = 320, Height = 240;

// The pixels the asset covers (alpha above one half): how many, their mean x and y, and
// the rows and columns they span.
struct Coverage {
    int pixels = 0;
    double x = 0.0, y = 0.0;
    int columns = 0, rows = 0;
};

Coverage coverageOf(const ReadImage& image) {
    const int a = image.channel("A");
    Coverage c;
    int left = image.width, right = -1, top = image.height, bottom = -1;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            if (!(image.at(x, y, a) > 0.5f)) continue;
            ++c.pixels;
            c.x += x + 0.5;
            c.y += y + 0.5;
            left = std::min(left, x), right = std::max(right, x), top = std::min(top, y), bottom = std::max(bottom, y);
        }
    if (c.pixels == 0) return c;
    c.x /= c.pixels;
    c.y /= c.pixels;
    c.columns = right - left + 1;
    c.rows = bottom - top + 1;
    return c;
}

// Two 5 mm spheres 40 mm apart (/Left at x = -20, /Right at +20), a light, and a camera
// 150 mm away on +Z whose x runs from -10 at time code 0 to +10 at 48 (or stays at 0).
std::string twoSpheres(bool animated) {
    using namespace test::usda;
    const std::string shot =
        animated ? translateSamples({{0, {-10, 0, 150}}, {48, {10, 0, 150}}}) : translate({0, 0, 150});
    return header("    timeCodesPerSecond = 24\n    startTimeCode = 0\n    endTimeCode = 48\n") +
           reference("Left", "./sphere.usda", translate({-20, 0, 0})) +
           reference("Right", "./sphere.usda", translate({20, 0, 0})) +
           pointLight("Key", "2000", translate({0, 30, 60})) + camera("Shot", shot);
}

ViewRun runScript(const SceneDir& dir, const std::string& script) {
    const std::filesystem::path file = dir.write("camera.script", script);
    return runOpalView(dir, "--size " + std::to_string(Width) + "x" + std::to_string(Height) + " --script " + shellWord(file));
}

TEST(CameraChoice, FrameSelectionFillsThePictureWithTheSelectedAssetAndFrameAllShowsBoth) {
    const SceneDir dir;
    dir.writeSphereAsset("sphere");
    const std::filesystem::path scene = dir.write("two.usda", twoSpheres(false));
    const ViewRun run = runScript(dir, "load " + scriptWord(scene) + "\nselect /Right\ncamera frame selection\n" +
                                           saveExr(dir, "selected.exr") + "camera frame\n" + saveExr(dir, "all.exr") + "quit\n");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Coverage selected = coverageOf(readImage(dir / "selected.exr")), all = coverageOf(readImage(dir / "all.exr"));
    std::cout << "frame selection: " << selected.columns << " x " << selected.rows << " pixels about (" << selected.x
              << ", " << selected.y << "); frame all: " << all.columns << " x " << all.rows << '\n';
    // The sphere's silhouette just touches the top and bottom (the smaller side).
    EXPECT_NEAR(selected.rows, Height, 6);
    EXPECT_NEAR(selected.columns, Height, 6);
    EXPECT_NEAR(selected.x, Width / 2.0, 1.5);
    EXPECT_NEAR(selected.y, Height / 2.0, 1.5);
    // Framing everything: both spheres, side by side across the picture's middle.
    EXPECT_LT(all.rows, Height / 2);
    EXPECT_GT(all.columns, 3 * all.rows);
    EXPECT_NEAR(all.x, Width / 2.0, 1.5);
}

TEST(CameraChoice, FrameSelectionTargetsTheSelectedMesh) {
    const SceneDir dir;
    dir.writeSphereAsset("sphere");
    OpalRenderDelegate delegate;
    view::ViewerModel model(delegate, 48, 32);
    model.open(dir.write("two.usda", twoSpheres(false)));
    for (const double x : {-20.0, 20.0}) {
        model.selectMesh(x < 0.0 ? "/Left" : "/Right");
        model.frameSelection();
        EXPECT_NEAR(model.camera.target.x, x, 1e-9);
        EXPECT_NEAR(model.camera.target.y, 0.0, 1e-9);
    }
}

TEST(CameraChoice, TheUsedSceneCameraFollowsSceneTime) {
    const SceneDir dir;
    dir.writeSphereAsset("sphere");
    const std::filesystem::path scene = dir.write("moving.usda", twoSpheres(true));
    std::string script = "load " + scriptWord(scene) + "\ncamera use /Shot\n";
    for (const int time : {0, 24, 48}) script += "time " + std::to_string(time) + "\n" + saveExr(dir, "t" + std::to_string(time) + ".exr");
    const ViewRun run = runScript(dir, script + "quit\n");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    // The camera at x = -10, 0, +10: the spheres' mean image x where a pinhole puts the origin.
    for (const int time : {0, 24, 48}) {
        const double cameraX = (time - 24) * 10.0 / 24.0;
        const double expected = Width / 2.0 * (1.0 - cameraX / 150.0 * 50.0 / 18.0);
        const Coverage c = coverageOf(readImage(dir / ("t" + std::to_string(time) + ".exr")));
        std::cout << "time code " << time << ": spheres about x = " << c.x << " (pinhole " << expected << ")\n";
        EXPECT_NEAR(c.x, expected, 1.5) << "time code " << time;
    }
}

TEST(CameraChoice, UsingACameraTheSceneLacksFailsNamingItsCameras) {
    const SceneDir dir;
    dir.writeSphereAsset("sphere");
    const std::filesystem::path scene = dir.write("two.usda", twoSpheres(false));
    const ViewRun run = runScript(dir, "load " + scriptWord(scene) + "\ncamera use /Nope\n");
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.err.find("camera.script:2: no camera </Nope> in the scene (cameras: </Shot>)"), std::string::npos) << run.err;
}

TEST(CameraChoice, FieldOfViewIsTheLensAndFarClippingHidesTheAsset) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    const double shortLens = 2.0 * std::atan(18.0 / 25.0) * 180.0 / std::numbers::pi;  // 25 mm on 36 mm film
    char fov[64];
    std::snprintf(fov, sizeof fov, "camera fov %.9f\n", shortLens);
    const ViewRun run = runScript(dir, "load " + scriptWord(asset) + "\n" + saveExr(dir, "long.exr") + fov +
                                           saveExr(dir, "short.exr") + "camera clip 0.5 2\n" + saveExr(dir, "clipped.exr") +
                                           "camera clip auto\n" + saveExr(dir, "unclipped.exr") + "quit\n");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Coverage longLens = coverageOf(readImage(dir / "long.exr")), wide = coverageOf(readImage(dir / "short.exr"));
    ASSERT_GT(wide.pixels, 500);
    std::cout << "covered pixels at 50 mm " << longLens.pixels << ", at " << shortLens << " degrees " << wide.pixels << '\n';
    EXPECT_NEAR(double(longLens.pixels) / wide.pixels, 4.0, 0.2);
    EXPECT_EQ(coverageOf(readImage(dir / "clipped.exr")).pixels, 0) << "the far plane is nearer than the sphere";
    EXPECT_EQ(coverageOf(readImage(dir / "unclipped.exr")).pixels, wide.pixels);

    const ViewRun refused = runScript(dir, "load " + scriptWord(asset) + "\ncamera clip 5 1\n");
    EXPECT_EQ(refused.exitCode, 1);
    EXPECT_NE(refused.err.find("camera.script:2: clipping range 5"), std::string::npos) << refused.err;
}

}  // namespace
}  // namespace opal::test
