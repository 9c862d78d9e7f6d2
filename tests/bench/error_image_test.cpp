// The error picture of `opal-bench accuracy` and `compare` (bench/error_image.h): grey is
// the relative luminance error over 5%, so a pixel 2% off is 0.4; unmeasured pixels are
// the dark blue; a pixel with no reference light but some in the engine is white.
#include "bench/error_image.h"
#include "schema/error.h"

#include <gtest/gtest.h>

#include <vector>

namespace opal::bench {
namespace {

TEST(ErrorImage, GreyIsTheRelativeLuminanceErrorOverFivePercent) {
    const std::vector<float> reference = {0.2f, 0.4f, 0.1f, 1.0f, 1.0f, 1.0f, 0.0f, 0.0f, 0.0f};
    const std::vector<float> engine = {0.204f, 0.408f, 0.102f, 5.0f, 0.0f, 0.0f, 0.1f, 0.1f, 0.1f};
    const std::vector<std::uint8_t> mask = {1, 0, 1};
    const Image image = luminanceErrorImage(3, 1, engine, reference, mask);
    const auto& px = image.pixels();
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(px[c], 0.4f, 1e-5f);  // 2% off in every channel
    EXPECT_FLOAT_EQ(px[3], 0.05f);                                // not measured: blue
    EXPECT_FLOAT_EQ(px[5], 0.3f);
    for (int c = 6; c < 9; ++c) EXPECT_FLOAT_EQ(px[c], 1.0f);     // light where none should be
}

TEST(ErrorImage, SizesThatDoNotMatchAreRefused) {
    const std::vector<float> rgb(6, 1.0f);
    const std::vector<std::uint8_t> mask(3, 1);
    EXPECT_THROW((void)luminanceErrorImage(3, 1, rgb, rgb, mask), Error);
}

}  // namespace
}  // namespace opal::bench
