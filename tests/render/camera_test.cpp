#include "delegate/image/camera_view.h"

#include "schema/error.h"
#include "tests/render/render_scene.h"

#include <gtest/gtest.h>

namespace opal {
namespace {

Imath::V3d directionOf(const Ray& ray) { return Imath::V3d(ray.direction()).normalized(); }

TEST(CameraView, LooksDownMinusZWithXRightAndYUp) {
    const CameraView view(test::frontCamera(10.0), 300, 200, "/Camera");
    const Ray centre = view.ray(150.0, 100.0);
    EXPECT_NEAR(centre.origin().z, 10.0f, 1e-6);
    EXPECT_NEAR(directionOf(centre).z, -1.0, 1e-12);
    EXPECT_FLOAT_EQ(centre.direction().z, -1.0f);  // t is the depth along the view axis
    EXPECT_GT(view.ray(299.5, 100.0).direction().x, 0.0f);  // the right edge looks toward +X
    EXPECT_GT(view.ray(150.0, 0.5).direction().y, 0.0f);    // the top row looks toward +Y
    EXPECT_EQ(centre.tNear(), 0.1f);
    EXPECT_EQ(centre.tFar(), 1.0e6f);
}

TEST(CameraView, FitsTheApertureInTheImage) {
    hd::CameraDesc desc = test::frontCamera();
    desc.focalLength = 50.0;
    desc.horizontalAperture = 36.0;
    desc.verticalAperture = 24.0;
    // The film's aspect: the left edge of the image is the left edge of the film.
    const CameraView same(desc, 360, 240, "/Camera");
    EXPECT_NEAR(same.ray(0.0, 120.0).direction().x, -18.0f / 50.0f, 1e-6);
    EXPECT_NEAR(same.ray(180.0, 0.0).direction().y, 12.0f / 50.0f, 1e-6);
    // A square image shows the whole width and extends the height.
    const CameraView square(desc, 100, 100, "/Camera");
    EXPECT_NEAR(square.ray(0.0, 50.0).direction().x, -18.0f / 50.0f, 1e-6);
    EXPECT_NEAR(square.ray(50.0, 0.0).direction().y, 18.0f / 50.0f, 1e-6);
    // A wide image shows the whole height and extends the width.
    const CameraView wide(desc, 400, 100, "/Camera");
    EXPECT_NEAR(wide.ray(200.0, 0.0).direction().y, 12.0f / 50.0f, 1e-6);
    EXPECT_NEAR(wide.ray(0.0, 50.0).direction().x, -48.0f / 50.0f, 1e-6);
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
    EXPECT_NEAR(centre.origin().x, 5.0f, 1e-5);
    EXPECT_NEAR(centre.origin().y, 1.0f, 1e-5);
    EXPECT_NEAR(directionOf(centre).x, -1.0, 1e-6);
    EXPECT_NEAR(Imath::V3d(centre.direction()).length(), 1.0, 1e-6);  // depth stays in world units
}

// Slab test: does the ray through a pixel centre meet the box within [tNear, tFar]?
bool rayMeetsBox(const Ray& ray, const Imath::Box3f& box) {
    double t0 = ray.tNear(), t1 = ray.tFar();
    for (int a = 0; a < 3; ++a) {
        const double inv = 1.0 / ray.direction()[a];
        double ta = (box.min[a] - ray.origin()[a]) * inv, tb = (box.max[a] - ray.origin()[a]) * inv;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta), t1 = std::min(t1, tb);
    }
    return t0 <= t1;
}

TEST(CameraView, PixelBoundsHoldEveryPixelWhoseRayMeetsTheBox) {
    hd::CameraDesc desc = test::frontCamera(10.0);
    Imath::M44d turn;
    turn.setAxisAngle(Imath::V3d(0.3, 1, 0.2).normalized(), 0.4);
    desc.transform = desc.transform * turn;
    const CameraView view(desc, 160, 90, "/Camera");
    for (const Imath::Box3f& box : {Imath::Box3f({-1, -1, -1}, {1, 1, 1}), Imath::Box3f({2, -0.5f, -3}, {3, 2, 0}),
                                    Imath::Box3f({-4, -4, -4}, {-3.5f, -3, -3.8f})}) {
        const CameraView::PixelRect r = view.pixelBounds(box);
        int inside = 0;
        for (int y = 0; y < 90; ++y)
            for (int x = 0; x < 160; ++x) {
                if (!rayMeetsBox(view.ray(x + 0.5, y + 0.5), box)) continue;
                ++inside;
                ASSERT_TRUE(x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1) << "pixel " << x << ", " << y;
            }
        EXPECT_GT(inside, 0);
        EXPECT_LT((r.x1 - r.x0) * (r.y1 - r.y0), 4 * inside + 400) << "the bounds should be tight";
    }
    // A box around the camera: the whole image. An empty box: nothing.
    const CameraView::PixelRect around = view.pixelBounds(Imath::Box3f({-20, -20, -20}, {20, 20, 20}));
    EXPECT_TRUE(around.x0 == 0 && around.y0 == 0 && around.x1 == 160 && around.y1 == 90);
    const CameraView::PixelRect none = view.pixelBounds(Imath::Box3f());
    EXPECT_FALSE(none.overlaps(0, 0, 160, 90));
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
