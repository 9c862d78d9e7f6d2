// The fan triangulation against triangles listed by hand: a triangle, a quad and a
// pentagon give 1 + 2 + 3 triangles from each face's first corner, in face order with
// the faces' winding; faces of fewer than three corners give none; counts that run past
// the indices are an error naming the face.
#include "schema/asset/fan_triangulation.h"

#include <gtest/gtest.h>

#include <array>
#include <utility>
#include <vector>

namespace opal {
namespace {

using Triangle = std::pair<std::size_t, std::array<std::int32_t, 3>>;  // face, vertices

std::vector<Triangle> fan(const std::vector<std::int32_t>& counts, const std::vector<std::int32_t>& indices) {
    std::vector<Triangle> triangles;
    forEachFanTriangle(counts, indices, [&](std::size_t face, const std::array<std::int32_t, 3>& v) {
        triangles.emplace_back(face, v);
    });
    return triangles;
}

TEST(FanTriangulation, EachFaceFansFromItsFirstCornerInOrder) {
    const std::vector<Triangle> expected = {
        {0, {7, 8, 9}},                                 // the triangle as it is
        {1, {0, 1, 2}}, {1, {0, 2, 3}},                 // the quad 0 1 2 3
        {2, {4, 5, 6}}, {2, {4, 6, 10}}, {2, {4, 10, 11}},  // the pentagon 4 5 6 10 11
    };
    EXPECT_EQ(fan({3, 4, 5}, {7, 8, 9, 0, 1, 2, 3, 4, 5, 6, 10, 11}), expected);
}

TEST(FanTriangulation, FacesOfFewerThanThreeCornersGiveNoTriangle) {
    const std::vector<Triangle> expected = {{2, {3, 4, 5}}};
    EXPECT_EQ(fan({2, 0, 3}, {0, 1, 3, 4, 5}), expected);
    EXPECT_TRUE(fan({}, {}).empty());
}

TEST(FanTriangulation, CountsRunningPastTheIndicesNameTheFace) {
    try {
        fan({3, 4}, {0, 1, 2, 0, 2, 3});
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "face 1 has 4 corners, past the 6 face-vertex indices");
    }
}

}  // namespace
}  // namespace opal
