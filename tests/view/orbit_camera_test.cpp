// The viewer's orbit camera against geometry worked out by hand: where the eye is, that
// framing makes the sphere touch the narrower side of the view, that tumbling keeps the
// distance, that a scene camera converts without moving, and that track follows the cursor.
#include "examples/opal-view/core/light_drag.h"
#include "examples/opal-view/core/orbit_camera.h"

#include <gtest/gtest.h>

#include <cmath>

namespace opal::view {
namespace {

void expectNear(const Imath::V3d& a, const Imath::V3d& b, double tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(OrbitCamera, YawAndPitchPlaceTheEyeAroundTheTarget) {
    OrbitCamera camera;
    camera.target = {1.0, 2.0, 3.0};
    camera.distance = 10.0;
    expectNear(eyePosition(camera), {1.0, 2.0, 13.0}, 1e-12);  // looking down -Z
    camera.yaw = 90.0;
    expectNear(eyePosition(camera), {11.0, 2.0, 3.0}, 1e-9);
    camera.yaw = 0.0;
    camera.pitch = 30.0;
    expectNear(eyePosition(camera), {1.0, 2.0 + 5.0, 3.0 + 10.0 * std::cos(M_PI / 6)}, 1e-9);
    // The camera's -Z axis points at the target.
    const Imath::M44d m = cameraToWorld(camera);
    const Imath::V3d forward = -Imath::V3d(m[2][0], m[2][1], m[2][2]);
    expectNear(forward, (camera.target - eyePosition(camera)).normalized(), 1e-12);
}

TEST(OrbitCamera, FramingMakesTheSphereTouchTheNarrowerSide) {
    OrbitCamera camera;
    camera.yaw = 33.0;
    camera.pitch = -12.0;
    const BoundingSphere sphere{{5.0, -2.0, 1.0}, 4.0};
    const double aspect = 16.0 / 9.0;
    frame(camera, sphere, aspect);
    EXPECT_EQ(camera.target, sphere.center);
    // The 36 x 24 film fitted into 16:9 shows all 24 mm vertically (and 42.7 across): the
    // half angle is atan(12 / 50); the sphere subtends asin(r / d).
    EXPECT_NEAR(std::asin(sphere.radius / camera.distance), std::atan(12.0 / 50.0), 1e-12);
    // In a tall viewport the 36 mm side is the narrower one shown.
    frame(camera, sphere, 0.5);
    EXPECT_NEAR(std::asin(sphere.radius / camera.distance), std::atan(18.0 / 50.0), 1e-12);
}

TEST(OrbitCamera, TumbleKeepsTheTargetAndDistanceAndStopsShortOfThePoles) {
    OrbitCamera camera;
    camera.target = {1.0, 1.0, 1.0};
    camera.distance = 7.0;
    tumble(camera, 200.0, 10000.0);
    EXPECT_NEAR((eyePosition(camera) - camera.target).length(), 7.0, 1e-9);
    EXPECT_EQ(camera.pitch, 89.0);
    EXPECT_NEAR(camera.yaw, -50.0, 1e-12);  // 0.25 degree per pixel, dragging right turns left
}

TEST(OrbitCamera, DollyScalesTheDistance) {
    OrbitCamera camera;
    camera.distance = 10.0;
    dolly(camera, 1.0);
    EXPECT_NEAR(camera.distance, 9.0, 1e-12);
    dolly(camera, -2.0);
    EXPECT_NEAR(camera.distance, 10.0 / 0.9, 1e-12);
}

TEST(OrbitCamera, TrackMovesTheTargetWithTheCursor) {
    OrbitCamera camera;
    camera.distance = 50.0;  // at 50 mm focal length the film's 24 mm spans 24 units
    track(camera, 100.0, 0.0, 480, 36.0 / 24.0);
    // Dragging right by 100 of 480 pixels slides the scene right: the target goes left.
    expectNear(camera.target, {-100.0 / 480.0 * 24.0, 0.0, 0.0}, 1e-9);
}

TEST(OrbitCamera, ASceneCameraConvertsWithoutMoving) {
    OrbitCamera original;
    original.target = {0.0, 50.0, 0.0};
    original.distance = 200.0;
    original.yaw = -40.0;
    original.pitch = 21.0;
    original.focalLength = 35.0;
    const BoundingSphere scene{{10.0, 40.0, 0.0}, 30.0};
    const hd::CameraDesc desc = cameraDesc(original, scene);
    const OrbitCamera converted = orbitFromCamera(desc, scene);
    expectNear(eyePosition(converted), eyePosition(original), 1e-9);
    EXPECT_NEAR(converted.yaw, original.yaw, 1e-9);
    EXPECT_NEAR(converted.pitch, original.pitch, 1e-9);
    EXPECT_EQ(converted.focalLength, 35.0);
    // The film is the camera's (the delegate fits it), and the clipping planes hold the
    // whole scene.
    EXPECT_EQ(desc.horizontalAperture, 36.0);
    EXPECT_EQ(desc.verticalAperture, 24.0);
    const double far = (eyePosition(original) - scene.center).length() + scene.radius;
    EXPECT_GE(desc.farClip, far);
    EXPECT_LE(desc.nearClip, (eyePosition(original) - scene.center).length() - scene.radius);
}

TEST(LightDrag, TheLightGoesWhereTheCursorPointsOnTheSphere) {
    OrbitCamera camera;
    camera.distance = 100.0;
    const Imath::V3d eye = eyePosition(camera), center(0.0, 0.0, 0.0);
    // The image centre: the sphere's point nearest the camera.
    expectNear(pointOnSphere(eye, viewRay(camera, 1.5, 0.0, 0.0), center, 20.0), {0.0, 0.0, 20.0}, 1e-9);
    // Right of centre: on the sphere, on the right, facing the camera, on the cursor's ray.
    const Imath::V3d ray = viewRay(camera, 1.5, 0.1, 0.0);
    const Imath::V3d p = pointOnSphere(eye, ray, center, 20.0);
    EXPECT_NEAR(p.length(), 20.0, 1e-9);
    EXPECT_GT(p.x, 0.0);
    EXPECT_GT(p.z, 0.0);
    EXPECT_NEAR(((p - eye).normalized() - ray).length(), 0.0, 1e-9);
    // Past the silhouette: on the sphere, at the silhouette's side (perpendicular to the view).
    const Imath::V3d q = pointOnSphere(eye, viewRay(camera, 1.5, 0.9, 0.0), center, 20.0);
    EXPECT_NEAR(q.length(), 20.0, 1e-9);
    EXPECT_GT(q.x, 18.0);  // (19.0, 0, 6.2) for this ray
}

}  // namespace
}  // namespace opal::view
