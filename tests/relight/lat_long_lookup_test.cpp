// The renderer's lat-long lookups against libm and LatLongMap::coordinates.
#include "delegate/image/lat_long_lookup.h"

#include "delegate/relight/environment_light.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace opal {
namespace {

TEST(FastAtan2, FloatIsWithin2e5Radians) {
    double worst = 0.0;
    // Every direction of the circle at 1e-4 rad steps, and the axes exactly.
    for (int i = 0; i <= 62832; ++i) {
        const double angle = -3.14159 + 1e-4 * i;
        const float x = float(std::cos(angle)), y = float(std::sin(angle));
        worst = std::max(worst, std::abs(double(fastAtan2(y, x)) - std::atan2(double(y), double(x))));
    }
    EXPECT_LT(worst, 2e-5);
    EXPECT_NEAR(fastAtan2(1.0f, 0.0f), M_PI / 2, 1e-6);
    EXPECT_NEAR(fastAtan2(0.0f, -1.0f), M_PI, 1e-6);
    EXPECT_NEAR(fastAtan2(-1.0f, 0.0f), -M_PI / 2, 1e-6);
    EXPECT_EQ(fastAtan2(0.0f, 0.0f), 0.0f);
}

TEST(LatLongCoordinates, AgreeWithTheMapsOrientation) {
    std::mt19937 rng(2);
    std::normal_distribution<double> normal;
    for (int i = 0; i < 20000; ++i) {
        const Imath::V3d d(normal(rng), normal(rng), normal(rng));
        const Imath::V2d exact = LatLongMap::coordinates(d);
        const Imath::V2f single = latLongCoordinates(Imath::V3f(d));
        // u wraps at the map's seam (-Z): compare on the circle.
        const double du = std::abs(single.x - exact.x);
        ASSERT_LT(std::min(du, 1.0 - du), 1e-5) << d;
        ASSERT_NEAR(single.y, exact.y, 1e-5) << d;
    }
}

}  // namespace
}  // namespace opal
