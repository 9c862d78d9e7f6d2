// haarLocalitySlots: the transfer product's input order (delegate/relight/haar_locality_order.h).
#include "delegate/relight/haar_locality_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace opal {
namespace {

// Mallat index of (row, column) in chart c of side S.
std::uint32_t mallat(std::uint32_t c, std::uint32_t S, std::uint32_t row, std::uint32_t column) {
    return c * S * S + row * S + column;
}

TEST(HaarLocalityOrder, IsAPermutationThatKeepsEachChartInItsOwnRange) {
    const ChartLayout layout{3, 4};  // 3 charts of 16 x 16
    const std::vector<std::uint32_t> slots = haarLocalitySlots(layout);
    ASSERT_EQ(slots.size(), layout.cells());
    std::vector<std::uint32_t> sorted = slots;
    std::sort(sorted.begin(), sorted.end());
    for (std::uint32_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);
    for (std::uint32_t j = 0; j < slots.size(); ++j) EXPECT_EQ(slots[j] / 256, j / 256) << "coefficient " << j;
}

// Coarse levels first (the scaling coefficient at each chart's start); within a level a
// place's three bands side by side; places in Morton order.
TEST(HaarLocalityOrder, LevelsCoarseToFineWithEachPlacesBandsTogether) {
    const std::uint32_t S = 8;
    const std::vector<std::uint32_t> slots = haarLocalitySlots(ChartLayout{2, 3});
    for (std::uint32_t c = 0; c < 2; ++c) {
        const std::uint32_t base = c * S * S;
        EXPECT_EQ(slots[mallat(c, S, 0, 0)], base);
        // Level 1 is (0,1), (1,0), (1,1); level 2 starts at slot 4 with place (0,0): bands
        // (0,2), (2,0), (2,2); then place (0,1): (0,3), (2,1), (2,3).
        EXPECT_EQ(slots[mallat(c, S, 0, 1)], base + 1);
        EXPECT_EQ(slots[mallat(c, S, 1, 0)], base + 2);
        EXPECT_EQ(slots[mallat(c, S, 1, 1)], base + 3);
        EXPECT_EQ(slots[mallat(c, S, 0, 2)], base + 4);
        EXPECT_EQ(slots[mallat(c, S, 2, 0)], base + 5);
        EXPECT_EQ(slots[mallat(c, S, 2, 2)], base + 6);
        EXPECT_EQ(slots[mallat(c, S, 0, 3)], base + 7);
        EXPECT_EQ(slots[mallat(c, S, 2, 1)], base + 8);
        EXPECT_EQ(slots[mallat(c, S, 2, 3)], base + 9);
        // The finest level (side 4) takes the last 48 slots, place (3,3)'s bands last.
        EXPECT_EQ(slots[mallat(c, S, 4, 0)], base + 16 + 1);
        EXPECT_EQ(slots[mallat(c, S, 7, 7)], base + 63);
        EXPECT_EQ(slots[mallat(c, S, 7, 3)], base + 62);
        EXPECT_EQ(slots[mallat(c, S, 3, 7)], base + 61);
    }
}

}  // namespace
}  // namespace opal
