#include "bake/point_kd_tree.h"

#include "bake/random.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <tbb/parallel_for.h>

namespace opal {
namespace {

// Random points plus exact duplicates and a lattice, so distance ties are common.
std::vector<Imath::V3f> testPoints() {
    std::vector<Imath::V3f> points;
    Random random(7, 0);
    for (int i = 0; i < 3000; ++i) {
        points.emplace_back(random.uniformFloat(), random.uniformFloat(), random.uniformFloat() * 0.1f);
    }
    for (int i = 0; i < 500; ++i) points.push_back(points[i * 3]);
    for (int x = 0; x < 10; ++x)
        for (int y = 0; y < 10; ++y) points.emplace_back(x * 0.1f, y * 0.1f, 0.5f);
    return points;
}

TEST(PointKdTree, RadiusSearchMatchesBruteForce) {
    std::vector<Imath::V3f> points = testPoints();
    PointKdTree tree(points);
    Random random(8, 0);
    std::vector<std::uint32_t> found;
    for (int q = 0; q < 200; ++q) {
        Imath::V3f query = q < 100 ? points[q * 31] : Imath::V3f(random.uniformFloat(), random.uniformFloat(), 0.5f);
        float radius = q % 2 ? 0.1f : 0.2f;  // 0.1 and 0.2: exactly the lattice spacing
        std::vector<std::uint32_t> expected;
        for (std::uint32_t i = 0; i < points.size(); ++i) {
            if ((points[i] - query).length2() <= radius * radius) expected.push_back(i);
        }
        tree.findWithinRadius(query, radius, found);
        EXPECT_EQ(found, expected) << "query " << q;
    }
}

TEST(PointKdTree, NearestMatchesBruteForceWithIndexTieBreak) {
    std::vector<Imath::V3f> points = testPoints();
    PointKdTree tree(points);
    std::vector<PointKdTree::Neighbour> found;
    for (int q = 0; q < 200; ++q) {
        Imath::V3f query = q < 100 ? points[q * 17] : Imath::V3f(0.05f * (q % 20), 0.3f, 0.5f);
        std::vector<PointKdTree::Neighbour> all;
        for (std::uint32_t i = 0; i < points.size(); ++i) all.push_back({i, (points[i] - query).length2()});
        std::sort(all.begin(), all.end(), [](auto& a, auto& b) {
            return a.distance2 < b.distance2 || (a.distance2 == b.distance2 && a.index < b.index);
        });
        for (std::size_t k : {1u, 8u, 33u}) {
            tree.findNearest(query, k, found);
            ASSERT_EQ(found.size(), k);
            for (std::size_t i = 0; i < k; ++i) {
                EXPECT_EQ(found[i].index, all[i].index) << "query " << q << " k " << k << " rank " << i;
                EXPECT_EQ(found[i].distance2, all[i].distance2);
            }
        }
    }
}

TEST(PointKdTree, HandlesTinyAndEmptySets) {
    std::vector<Imath::V3f> none;
    PointKdTree empty(none);
    std::vector<PointKdTree::Neighbour> found;
    empty.findNearest({0, 0, 0}, 3, found);
    EXPECT_TRUE(found.empty());
    std::vector<Imath::V3f> two = {{0, 0, 0}, {1, 0, 0}};
    PointKdTree small(two);
    small.findNearest({0.9f, 0, 0}, 5, found);
    ASSERT_EQ(found.size(), 2u);
    EXPECT_EQ(found[0].index, 1u);
    EXPECT_EQ(found[1].index, 0u);
}

}  // namespace
}  // namespace opal
