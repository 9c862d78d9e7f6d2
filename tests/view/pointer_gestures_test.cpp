// The viewport's mouse conventions: Alt + left tumbles, Alt + middle tracks, Alt + right
// and the wheel dolly, plain moves do nothing to the camera; a left drag without Alt moves
// the light to the cursor on its sphere, and with Alt leaves it.
#include "examples/opal-view/core/light_drag.h"
#include "examples/opal-view/core/pointer_gestures.h"

#include <gtest/gtest.h>

namespace opal::view {
namespace {

Pointer drag(double dx, double dy, bool left, bool middle, bool right, bool alt) {
    Pointer pointer;
    pointer.x = 400.0;
    pointer.y = 300.0;
    pointer.dx = dx;
    pointer.dy = dy;
    pointer.left = left;
    pointer.middle = middle;
    pointer.right = right;
    pointer.alt = alt;
    pointer.width = 800.0;
    pointer.height = 600.0;
    return pointer;
}

OrbitCamera start() {
    OrbitCamera camera;
    camera.distance = 100.0;
    return camera;
}

TEST(PointerGestures, AltDragsMoveTheCameraAsUsdview) {
    OrbitCamera tumbled = start(), tracked = start(), dollied = start(), plain = start();
    EXPECT_TRUE(cameraGesture(tumbled, drag(40.0, 0.0, true, false, false, true)));
    EXPECT_NEAR(tumbled.yaw, -10.0, 1e-12);
    EXPECT_EQ(tumbled.target, start().target);
    EXPECT_TRUE(cameraGesture(tracked, drag(40.0, 0.0, false, true, false, true)));
    EXPECT_LT(tracked.target.x, 0.0);
    EXPECT_EQ(tracked.distance, 100.0);
    EXPECT_TRUE(cameraGesture(dollied, drag(20.0, 0.0, false, false, true, true)));
    EXPECT_NEAR(dollied.distance, 90.0, 1e-9);
    EXPECT_FALSE(cameraGesture(plain, drag(40.0, 40.0, true, false, false, false)));
    EXPECT_EQ(plain.yaw, 0.0);
    EXPECT_EQ(plain.distance, 100.0);
}

TEST(PointerGestures, TheWheelDollies) {
    OrbitCamera camera = start();
    Pointer pointer = drag(0.0, 0.0, false, false, false, false);
    pointer.wheel = 2.0;
    EXPECT_TRUE(cameraGesture(camera, pointer));
    EXPECT_NEAR(camera.distance, 81.0, 1e-9);
}

TEST(PointerGestures, ALeftDragWithoutAltMovesTheLightToTheCursor) {
    const OrbitCamera camera = start();
    const Imath::V3d light(0.0, 30.0, 0.0), center(0.0, 0.0, 0.0);
    Pointer pointer = drag(5.0, 0.0, true, false, false, false);
    pointer.x = 600.0;  // right of centre
    const std::optional<Imath::V3d> moved = lightGesture(camera, pointer, light, center);
    ASSERT_TRUE(moved);
    EXPECT_NEAR(moved->length(), 30.0, 1e-9);
    EXPECT_GT(moved->x, 0.0);
    const Imath::V3d ray = viewRay(camera, 800.0 / 600.0, 0.5, 0.0);
    EXPECT_EQ(*moved, pointOnSphere(eyePosition(camera), ray, center, 30.0));
    EXPECT_FALSE(lightGesture(camera, drag(5.0, 0.0, true, false, false, true), light, center));
    EXPECT_FALSE(lightGesture(camera, drag(0.0, 0.0, true, false, false, false), light, center));
}

}  // namespace
}  // namespace opal::view
