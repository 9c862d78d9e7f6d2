// The sub-pixel sample pattern (image/sample_pattern.h): stratification, determinism, and
// its error on straight edges against exact areas, every orientation and offset.
#include "delegate/image/sample_pattern.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <vector>

namespace opal {
namespace {

TEST(SamplePattern, SixteenSamplesFillEveryElementaryInterval) {
    // A (0, 4, 2)-net: one sample in each cell of 1 x 16, 2 x 8, 4 x 4, 8 x 2, 16 x 1 grids.
    for (int columnsLog2 = 0; columnsLog2 <= 4; ++columnsLog2) {
        const int columns = 1 << columnsLog2, rows = 16 / columns;
        std::set<int> cells;
        for (std::uint32_t k = 0; k < 16; ++k) {
            const Imath::V2f p = samplePosition(k);
            ASSERT_GE(p.x, 0.0f);
            ASSERT_LT(p.x, 1.0f);
            ASSERT_GE(p.y, 0.0f);
            ASSERT_LT(p.y, 1.0f);
            cells.insert(int(p.x * columns) + columns * int(p.y * rows));
        }
        EXPECT_EQ(cells.size(), 16u) << columns << " x " << rows;
    }
    // Each power-of-two prefix is stratified too (what a pass in progress shows).
    std::set<int> quarters;
    for (std::uint32_t k = 0; k < 4; ++k) quarters.insert(int(samplePosition(k).x * 2) + 2 * int(samplePosition(k).y * 2));
    EXPECT_EQ(quarters.size(), 4u);
}

// The area of the unit square on the side n.p < c.
double area(double nx, double ny, double c) {
    const double corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    std::vector<std::pair<double, double>> clipped;
    for (int i = 0; i < 4; ++i) {
        const double* p = corners[i];
        const double* q = corners[(i + 1) % 4];
        const double dp = nx * p[0] + ny * p[1] - c, dq = nx * q[0] + ny * q[1] - c;
        if (dp < 0) clipped.emplace_back(p[0], p[1]);
        if ((dp < 0) != (dq < 0)) {
            const double t = dp / (dp - dq);
            clipped.emplace_back(p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]));
        }
    }
    double twice = 0.0;
    for (std::size_t i = 0; i < clipped.size(); ++i) {
        const auto& [px, py] = clipped[i];
        const auto& [qx, qy] = clipped[(i + 1) % clipped.size()];
        twice += px * qy - qx * py;
    }
    return std::abs(twice) / 2.0;
}

// The largest |fraction of samples - area| over edges of one orientation: the fraction only
// changes where the edge passes a sample, so just before and after each one.
double worstEdgeError(double degrees) {
    const double nx = std::cos(degrees * std::numbers::pi / 180.0), ny = std::sin(degrees * std::numbers::pi / 180.0);
    std::vector<double> d;
    for (std::uint32_t k = 0; k < 16; ++k) d.push_back(nx * samplePosition(k).x + ny * samplePosition(k).y);
    std::sort(d.begin(), d.end());
    double worst = 0.0;
    for (std::size_t k = 0; k < d.size(); ++k) {
        const double a = area(nx, ny, d[k]);
        worst = std::max({worst, std::abs(double(k) / 16.0 - a), std::abs(double(k + 1) / 16.0 - a)});
    }
    return worst;
}

TEST(SamplePattern, StraightEdgesAreWithinOneEighthOfThePixelWhateverTheirOrientation) {
    double worst = 0.0, mean = 0.0;
    for (int a = 0; a < 360; ++a) {
        const double e = worstEdgeError(a * 0.5 + 0.25);
        worst = std::max(worst, e);
        mean += e / 360.0;
    }
    std::printf("16 samples on straight edges: worst %.4f, mean of each orientation's worst %.4f\n", worst, mean);
    EXPECT_LT(worst, 0.125);
    EXPECT_LT(mean, 0.1);
    // Edges near the axes and 10-20 degrees off them: within one sample's weight plus 2%.
    for (double degrees : {0.5, 10.0, 15.0, 90.5, 100.0, 105.0})
        EXPECT_LT(worstEdgeError(degrees), 1.0 / 16.0 + 0.02) << degrees;
}

}  // namespace
}  // namespace opal
