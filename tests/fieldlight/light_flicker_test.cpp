// lightFlicker (delegate/relight/light_flicker.h): none at amplitude 0, bounded by the
// amplitude, smooth in time, the same for the same inputs, different for another seed.
#include "delegate/relight/light_flicker.h"

#include "schema/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace opal {
namespace {

TEST(LightFlicker, AmplitudeZeroIsASteadyLight) {
    for (double t : {0.0, 0.3, 17.5, -4.0}) {
        const FlickerState s = lightFlicker({0.0, 8.0, 9}, t);
        EXPECT_EQ(s.intensity, 1.0);
        EXPECT_EQ(s.offset, Imath::V3d(0.0));
    }
}

TEST(LightFlicker, BoundedSmoothAndRepeatable) {
    const hd::LightFlicker flicker{0.3, 8.0, 42};
    double lo = 10.0, hi = -10.0, mean = 0.0, worstStep = 0.0;
    const int n = 20000;
    const double dt = 1e-3;  // s: 1/125 of a flicker period
    FlickerState previous = lightFlicker(flicker, 0.0);
    for (int i = 1; i <= n; ++i) {
        const FlickerState s = lightFlicker(flicker, i * dt);
        lo = std::min(lo, s.intensity);
        hi = std::max(hi, s.intensity);
        mean += s.intensity / n;
        worstStep = std::max(worstStep, std::abs(s.intensity - previous.intensity));
        EXPECT_LE(s.offset.length(), 0.3 / 4.0 * std::sqrt(3.0) + 1e-12);
        previous = s;
    }
    EXPECT_GE(lo, 1.0 - 0.3);
    EXPECT_LE(hi, 1.0 + 0.3);
    EXPECT_GT(hi - lo, 0.2);             // it does flicker
    EXPECT_NEAR(mean, 1.0, 0.05);        // about the steady intensity
    EXPECT_LT(worstStep, 0.3 * 0.1);     // no jumps between close times
    EXPECT_EQ(lightFlicker(flicker, 1.234).intensity, lightFlicker(flicker, 1.234).intensity);
    EXPECT_NE(lightFlicker({0.3, 8.0, 43}, 1.234).intensity, lightFlicker(flicker, 1.234).intensity);
}

TEST(LightFlicker, RejectsBadInput) {
    EXPECT_THROW(lightFlicker({-0.1, 8.0, 0}, 0.0), Error);
    EXPECT_THROW(lightFlicker({0.1, std::nan(""), 0}, 0.0), Error);
    EXPECT_THROW(lightFlicker({0.1, 8.0, 0}, std::numeric_limits<double>::infinity()), Error);
    EXPECT_NO_THROW(lightFlicker({0.1, 8.0, 0}, 1e300));  // far times stay finite
}

}  // namespace
}  // namespace opal
