// viewedRadiance and viewAxes (schema/asset/emitter_views.h) on views made in code: a disk
// image of known radius is seen where the ray passes within it, interpolation reproduces a
// linear ramp exactly, the axes are an orthonormal right-handed frame facing the viewer.
#include "schema/asset/cube_map.h"
#include "schema/asset/emitter_views.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace opal {
namespace {

// Every view shows f(x, y) at its pixel centres (x, y in units of the bounding radius).
EmitterViews viewsOf(std::uint32_t faceSize, std::uint32_t imageSize, const std::function<float(double, double)>& f) {
    EmitterViews v;
    v.directionFaceSize = faceSize;
    v.imageSize = imageSize;
    for (std::uint32_t k = 0; k < v.views(); ++k)
        for (std::uint32_t j = 0; j < imageSize; ++j)
            for (std::uint32_t i = 0; i < imageSize; ++i) {
                const float value = f(2.0 * (i + 0.5) / imageSize - 1.0, 2.0 * (j + 0.5) / imageSize - 1.0);
                for (int c = 0; c < 3; ++c) v.radiance.push_back(value * float(c + 1));
            }
    return v;
}

TEST(EmitterViews, AxesFaceTheViewer) {
    for (const Imath::V3d& v : {Imath::V3d(1, 0, 0), Imath::V3d(0, 1, 0), Imath::V3d(0, -1, 0),
                                Imath::V3d(0.3, -0.4, 0.866).normalized()}) {
        Imath::V3d right, up;
        viewAxes(v, right, up);
        EXPECT_NEAR(right.length(), 1.0, 1e-12);
        EXPECT_NEAR(up.length(), 1.0, 1e-12);
        EXPECT_NEAR(right.dot(up), 0.0, 1e-12);
        EXPECT_NEAR(right.dot(v), 0.0, 1e-12);
        EXPECT_NEAR((right.cross(up) - v).length(), 0.0, 1e-12);  // right-handed, v toward the viewer
    }
}

TEST(EmitterViews, ADiskIsSeenWithinItsRadius) {
    const double radius = 3.0;  // the bounding radius; the disk is half of it
    const EmitterViews views = viewsOf(2, 64, [](double x, double y) { return x * x + y * y < 0.25 ? 1.0f : 0.0f; });
    // Along a view's own direction, so that one view answers (between views, an offset is
    // foreshortened by the cosine between them: the views' spacing sets that error).
    const Imath::V3d d = -Imath::V3d(CubeMapLayout(2).direction(5));
    Imath::V3d right, up;
    viewAxes(-d, right, up);
    EXPECT_NEAR(viewedRadiance(views, radius, d, Imath::V3d(0.0)).y, 2.0f, 1e-6f);
    EXPECT_NEAR(viewedRadiance(views, radius, d, right * (0.4 * radius)).x, 1.0f, 1e-6f);
    EXPECT_EQ(viewedRadiance(views, radius, d, up * (0.6 * radius)).x, 0.0f);
    EXPECT_EQ(viewedRadiance(views, radius, d, right * (1.01 * radius)), Imath::V3f(0.0f));  // outside the disk
    EXPECT_EQ(viewedRadiance(EmitterViews{}, radius, d, Imath::V3d(0.0)), Imath::V3f(0.0f));  // no views
}

TEST(EmitterViews, BilinearReproducesALinearRampBetweenPixelCentres) {
    const EmitterViews views = viewsOf(1, 16, [](double x, double y) { return float(2.0 + x + 0.5 * y); });
    const Imath::V3d v(0.0, 0.0, 1.0);  // the centre of the +Z face: one view
    Imath::V3d right, up;
    viewAxes(v, right, up);
    const double radius = 2.0;
    for (double x : {-0.8, -0.3, 0.1, 0.55, 0.9})
        for (double y : {-0.7, 0.0, 0.65}) {
            const Imath::V3f seen = viewedRadiance(views, radius, -v, (right * x + up * y) * radius);
            const double expected = x * x + y * y < 1.0 ? 2.0 + x + 0.5 * y : 0.0;  // outside the disk: nothing
            EXPECT_NEAR(seen.x, expected, 1e-5) << x << "," << y;
        }
}

}  // namespace
}  // namespace opal
