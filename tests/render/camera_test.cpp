#include "delegate/camera.h"

#include "schema/error.h"
#include "tests/render/render_scene.h"

#include <gtest/gtest.h>

namespace opal {
namespace {

Imath::V3d directionOf(const Ray& ray) { return Imath::V3d(ray.direction).normalized(); }

TEST(CameraView, LooksDownMinusZWithXRightAndYUp) {
    const CameraView view(test::frontCamera(10.0), 300, 200, "/Camera");
    const Ray centre = view.ray(150.0, 100.0);
    EXPECT_NEAR(centre.origin.z, 10.0f, 1e-6);
    EXPECT_NEAR(directionOf(centre).z, -1.0, 1e-12);
    EXPECT_FLOAT_EQ(centre.direction.z, -1.0f);  // t is the depth along the view axis
    EXPECT_GT(view.ray(299.5, 100.0).direction.x, 0.0f);  // the right edge looks toward +X
    EXPECT_GT(view.ray(150.0, 0.5).direction.y, 0.0f);    // the top row looks toward +Y
    EXPECT_EQ(centre.tNear, 0.1f);
    EXPECT_EQ(centre.tFar, 1.0e6f);
}

TEST(CameraView, FitsTheApertureInTheImage) {
    hd::CameraDesc desc = test::frontCamera();
    desc.focalLength = 50.0;
    desc.horizontalAperture = 36.0;
    desc.verticalAperture = 24.0;
    // The film's aspect: the left edge of the image is the left edge of the film.
    const CameraView same(desc, 360, 240, "/Camera");
    EXPECT_NEAR(same.ray(0.0, 120.0).direction.x, -18.0f / 50.0f, 1e-6);
    EXPECT_NEAR(same.ray(180.0, 0.0).direction.y, 12.0f / 50.0f, 1e-6);
    // A square image shows the whole width and extends the height.
    const CameraView square(desc, 100, 100, "/Camera");
    EXPECT_NEAR(square.ray(0.0, 50.0).direction.x, -18.0f / 50.0f, 1e-6);
    EXPECT_NEAR(square.ray(50.0, 0.0).direction.y, 18.0f / 50.0f, 1e-6);
    // A wide image shows the whole height and extends the width.
    const CameraView wide(desc, 400, 100, "/Camera");
    EXPECT_NEAR(wide.ray(200.0, 0.0).direction.y, 12.0f / 50.0f, 1e-6);
    EXPECT_NEAR(wide.ray(0.0, 50.0).direction.x, -48.0f / 50.0f, 1e-6);
}

TEST(CameraView, FollowsTheCameraTransform) {
    hd::CameraDesc desc;
    // Turned 90 degrees about +Y: -Z maps to -X; placed at (5, 1, 2), scaled by 3 (ignored).
    Imath::M44d m;
    m.setAxisAngle(Imath::V3d(0, 1, 0), std::numbers::pi / 2);
    Imath::M44d scale;
    scale.setScale(3.0);
    desc.transform = scale * m * test::translation(5, 1, 2);
    const CameraView view(desc, 64, 64, "/Camera");
    const Ray centre = view.ray(32.0, 32.0);
    EXPECT_NEAR(centre.origin.x, 5.0f, 1e-5);
    EXPECT_NEAR(centre.origin.y, 1.0f, 1e-5);
    EXPECT_NEAR(directionOf(centre).x, -1.0, 1e-6);
    EXPECT_NEAR(Imath::V3d(centre.direction).length(), 1.0, 1e-6);  // depth stays in world units
}

TEST(CameraView, RejectsBadCamerasNamingThePrim) {
    hd::CameraDesc desc;
    desc.focalLength = 0.0;
    try {
        (void)CameraView(desc, 10, 10, "/World/BadCamera");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("/World/BadCamera"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("focal length"), std::string::npos) << e.what();
    }
    desc = {};
    desc.nearClip = 5.0;
    desc.farClip = 1.0;
    EXPECT_THROW(CameraView(desc, 10, 10, "/c"), Error);
    desc = {};
    desc.transform.setScale(Imath::V3d(1, 2, 1));
    EXPECT_THROW(CameraView(desc, 10, 10, "/c"), Error);
    EXPECT_THROW(CameraView(hd::CameraDesc{}, 0, 10, "/c"), Error);
}

}  // namespace
}  // namespace opal
