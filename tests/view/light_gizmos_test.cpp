// The light gizmos and the distant light's drag, without a window and on screen. Truths: a
// pinhole camera's closed-form projection (a point 1 mm off the axis at 10 mm, through a
// 50 mm lens, lies 5 mm off the film's centre); the inverse of the drag's own view ray;
// Rodrigues' rotation about the camera's up and right axes for a turned distant light; and
// the screenshot's pixels where the lights project, with the gizmos on and off.
#include "examples/opal-view/core/light_drag.h"
#include "examples/opal-view/core/light_gizmos.h"
#include "examples/opal-view/core/pointer_gestures.h"
#include "tests/support/scene_usda.h"
#include "tests/view/view_process.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace opal::view {
namespace {

// Looking down -Z from (0, 0, 30) at the origin; a 36 x 24 mm film behind a 50 mm lens.
OrbitCamera axisCamera() {
    OrbitCamera camera;
    camera.distance = 30.0;
    return camera;
}

hd::LightDesc lightAt(hd::LightKind kind, const Imath::V3d& at) {
    hd::LightDesc light;
    light.kind = kind;
    light.transform.setTranslation(at);
    return light;
}

// v rotated by `degrees` about the unit `axis`, right-handed (Rodrigues).
Imath::V3d rotated(const Imath::V3d& v, const Imath::V3d& axis, double degrees) {
    const double a = degrees * std::numbers::pi / 180.0;
    return v * std::cos(a) + axis.cross(v) * std::sin(a) + axis * (axis.dot(v) * (1.0 - std::cos(a)));
}

Imath::V3d axisZ(const hd::LightDesc& light) { return {light.transform[2][0], light.transform[2][1], light.transform[2][2]}; }

void expectSameDirection(const Imath::V3d& a, const Imath::V3d& b, double tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(LightGizmos, APointProjectsAsAPinholeCameraThroughTheFittedFilm) {
    // 960 x 540 is wider than 36 x 24: the film's 24 mm height spans 540 pixels.
    const std::optional<Imath::V2d> p = projectToViewport(axisCamera(), 960.0, 540.0, {1.0, 1.0, 20.0});
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->x, 480.0 + 5.0 * 540.0 / 24.0, 1e-9);
    EXPECT_NEAR(p->y, 270.0 - 5.0 * 540.0 / 24.0, 1e-9);
    // 400 x 400 is narrower: the 36 mm width spans 400 pixels.
    const std::optional<Imath::V2d> q = projectToViewport(axisCamera(), 400.0, 400.0, {-2.0, 0.0, 10.0});
    ASSERT_TRUE(q);
    EXPECT_NEAR(q->x, 200.0 - 5.0 * 400.0 / 36.0, 1e-9);
    EXPECT_NEAR(q->y, 200.0, 1e-9);
    EXPECT_FALSE(projectToViewport(axisCamera(), 960.0, 540.0, {0.0, 0.0, 30.0}));
    EXPECT_FALSE(projectToViewport(axisCamera(), 960.0, 540.0, {1.0, 0.0, 40.0}));
}

TEST(LightGizmos, TheDragsViewRayThroughAProjectedPointMeetsThePoint) {
    OrbitCamera camera = axisCamera();
    camera.yaw = 35.0;
    camera.pitch = -20.0;
    camera.target = {3.0, -1.0, 2.0};
    const Imath::V3d point(5.0, 2.0, 4.0);
    const std::optional<Imath::V2d> p = projectToViewport(camera, 640.0, 360.0, point);
    ASSERT_TRUE(p);
    const Imath::V3d ray = viewRay(camera, 640.0 / 360.0, 2.0 * p->x / 640.0 - 1.0, 1.0 - 2.0 * p->y / 360.0);
    const Imath::V3d toPoint = (point - eyePosition(camera)).normalized();
    expectSameDirection(ray, toPoint, 1e-12);
}

TEST(LightGizmos, MarkersForPositionalLightsArrowsForDistantOnesNoneForTheDome) {
    scene::Scene scene;
    scene.lights["/Bulb"] = {hd::PrimType::SphereLight, lightAt(hd::LightKind::Sphere, {1.0, 1.0, 20.0}), {}};
    scene.lights["/Flame"] = {hd::PrimType::ShadowFieldLight, lightAt(hd::LightKind::ShadowField, {-1.0, 0.0, 20.0}), {}};
    scene.lights["/Sky"] = {hd::PrimType::DomeLight, lightAt(hd::LightKind::Dome, Imath::V3d(0.0)), {}};
    scene.lights["/Behind"] = {hd::PrimType::SphereLight, lightAt(hd::LightKind::Sphere, {0.0, 0.0, 50.0}), {}};
    hd::LightDesc sun = lightAt(hd::LightKind::Distant, Imath::V3d(0.0));
    sun.transform.setAxisAngle(Imath::V3d(0.0, 1.0, 0.0), std::numbers::pi / 2.0);  // +Z turned to -X or +X
    scene.lights["/Sun"] = {hd::PrimType::DistantLight, sun, {}};
    const OrbitCamera camera = axisCamera();
    const GizmoView view{&camera, 960.0, 540.0, {{0.0, 0.0, 0.0}, 2.0}, std::string("/Sun")};
    const std::vector<LightGizmo> gizmos = lightGizmos(scene, view);
    ASSERT_EQ(gizmos.size(), 3u);
    EXPECT_EQ(gizmos[0].light, "/Bulb");
    EXPECT_EQ(gizmos[0].shape, LightGizmo::Shape::Marker);
    EXPECT_EQ(gizmos[0].at, *projectToViewport(camera, 960.0, 540.0, {1.0, 1.0, 20.0}));
    EXPECT_FALSE(gizmos[0].selected);
    EXPECT_EQ(gizmos[1].light, "/Flame");
    EXPECT_EQ(gizmos[2].light, "/Sun");
    EXPECT_EQ(gizmos[2].shape, LightGizmo::Shape::Arrow);
    EXPECT_TRUE(gizmos[2].selected);
    // The sun comes from its +Z: the arrow runs from 5 to 2.5 (2.5 and 1.25 radii) along it
    // to the object, in the plane y = 0: a horizontal arrow through the picture's centre row.
    const Imath::V3d z = axisZ(sun);
    EXPECT_EQ(gizmos[2].from, *projectToViewport(camera, 960.0, 540.0, z * 5.0));
    EXPECT_EQ(gizmos[2].at, *projectToViewport(camera, 960.0, 540.0, z * 2.5));
    EXPECT_NEAR(gizmos[2].at.y, 270.0, 1e-9);
    EXPECT_GT(std::abs(gizmos[2].from.x - 480.0), std::abs(gizmos[2].at.x - 480.0)) << "pointing at the object";
}

TEST(DistantLightDrag, ADragTurnsTheLightAboutTheCamerasUpThenRightAxis) {
    OrbitCamera camera = axisCamera();
    hd::LightDesc sun = lightAt(hd::LightKind::Distant, {7.0, 8.0, 9.0});
    // Straight on, 360 pixels right is a quarter turn about +Y: the light comes from +X.
    const hd::LightDesc right = turnedLight(camera, sun, 360.0, 0.0);
    expectSameDirection(axisZ(right), {1.0, 0.0, 0.0}, 1e-12);
    EXPECT_EQ(right.transform[3][0], 7.0);
    EXPECT_EQ(right.transform[3][2], 9.0);
    expectSameDirection(axisZ(turnedLight(camera, sun, 0.0, 360.0)), {0.0, -1.0, 0.0}, 1e-12);  // down: from below

    // From any camera: Rodrigues about its up axis by dx / 4 degrees, then about its right axis.
    camera.yaw = -50.0;
    camera.pitch = 30.0;
    const Imath::V3d back = (eyePosition(camera) - camera.target).normalized();
    const Imath::V3d rightAxis = Imath::V3d(0.0, 1.0, 0.0).cross(back).normalized(), up = back.cross(rightAxis);
    sun.transform.setEulerAngles(Imath::V3d(0.4, -1.1, 0.3));
    const hd::LightDesc turned = turnedLight(camera, sun, 44.0, -28.0);
    for (int axis = 0; axis < 3; ++axis) {
        const Imath::V3d before(sun.transform[axis][0], sun.transform[axis][1], sun.transform[axis][2]);
        const Imath::V3d after(turned.transform[axis][0], turned.transform[axis][1], turned.transform[axis][2]);
        expectSameDirection(after, rotated(rotated(before, up, 11.0), rightAxis, -7.0), 1e-12);
    }
}

TEST(DistantLightDrag, OnlyALeftDragWithoutAltTurnsIt) {
    const OrbitCamera camera = axisCamera();
    const hd::LightDesc sun = lightAt(hd::LightKind::Distant, Imath::V3d(0.0));
    Pointer pointer;
    pointer.left = true;
    pointer.dx = 40.0;
    const std::optional<hd::LightDesc> turned = distantLightGesture(camera, pointer, sun);
    ASSERT_TRUE(turned);
    expectSameDirection(axisZ(*turned), axisZ(turnedLight(camera, sun, 40.0, 0.0)), 0.0);
    pointer.alt = true;  // a tumble
    EXPECT_FALSE(distantLightGesture(camera, pointer, sun));
    pointer.alt = pointer.left = false;
    EXPECT_FALSE(distantLightGesture(camera, pointer, sun));
}

}  // namespace
}  // namespace opal::view

namespace opal::test {
namespace {

// The 5 mm sphere at the origin, seen from (0, 0, 30) down -Z, two point lights 10 mm in
// front of the camera: /A (selected: the first) 1 mm up and right, /B 1 mm down and left.
std::string gizmoScene() {
    using namespace usda;
    return header() + reference("Sphere", "./sphere.usda") + pointLight("A", "300", translate({1, 1, 20})) +
           pointLight("B", "300", translate({-1, -1, 20})) + camera("Camera", translate({0, 0, 30}));
}

// Whether the 3 x 3 pixels around (x, y) of an 8-bit screenshot all have `color`.
bool showsGizmoColor(const ReadImage& shot, int x, int y, const std::array<std::uint8_t, 3>& color) {
    for (int j = y - 1; j <= y + 1; ++j)
        for (int i = x - 1; i <= x + 1; ++i)
            for (int c = 0; c < 3; ++c)
                if (std::lround(shot.at(i, j, c) * 255.0f) != color[c]) return false;
    return true;
}

TEST(LightGizmos, TheScreenshotShowsAMarkerWhereEachLightProjectsUnlessTheyAreOff) {
    const SceneDir dir;
    dir.writeSphereAsset("sphere");
    dir.write("scene.usda", gizmoScene());
    dir.write("gizmos.script", "wait\nscreenshot " + scriptWord(dir / "on.png") + "\ngizmos off\nwait\nscreenshot " +
                                   scriptWord(dir / "off.png") + "\ngizmos on\nwait\nscreenshot " +
                                   scriptWord(dir / "again.png") + "\nquit\n");
    const ViewRun run =
        runOpalView(dir, shellWord(dir / "scene.usda") + " --size 960x540 --script " + shellWord(dir / "gizmos.script"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const ReadImage on = readImage(dir / "on.png"), off = readImage(dir / "off.png"), again = readImage(dir / "again.png");
    ASSERT_EQ(on.width, 960);
    // 1 mm off the axis at 10 mm through 50 mm: 5 mm on a film whose 24 mm span 540 pixels.
    const int offset = int(std::lround(5.0 * 540.0 / 24.0));
    const int ax = 480 + offset, ay = 270 - offset, bx = 480 - offset, by = 270 + offset;
    EXPECT_TRUE(showsGizmoColor(on, ax, ay, view::kSelectedGizmoColor)) << "the selected light /A";
    EXPECT_TRUE(showsGizmoColor(on, bx, by, view::kGizmoColor)) << "/B";
    EXPECT_FALSE(showsGizmoColor(on, ax, ay, view::kGizmoColor));
    EXPECT_FALSE(showsGizmoColor(off, ax, ay, view::kSelectedGizmoColor));
    EXPECT_FALSE(showsGizmoColor(off, bx, by, view::kGizmoColor));
    EXPECT_TRUE(showsGizmoColor(again, bx, by, view::kGizmoColor));
    // Far from both markers the gizmos change nothing.
    EXPECT_EQ(on.at(700, 400, 0), off.at(700, 400, 0));
}

}  // namespace
}  // namespace opal::test
