// Each xformOp's matrix against matrices computed by hand (row vectors, p' = p M, as USD and
// Imath): single-axis rotations, the three-axis rotation orders, quaternions, inverted
// entries, and the op names and xformOpOrder entries that are recognised.
#include "schema/error.h"
#include "schema/usd/xform_op.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace opal::usda {
namespace {

using Rows = std::array<std::array<double, 4>, 4>;

void expectMatrix(const Imath::M44d& actual, const Rows& expected) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(actual[r][c], expected[r][c], 1e-12) << "row " << r << ", column " << c;
}

TEST(XformOp, SingleAxisRotationsTurnCounterClockwise) {
    // Rx(90): y -> z, z -> -y.
    expectMatrix(rotateMatrix(0, 90.0), {{{1, 0, 0, 0}, {0, 0, 1, 0}, {0, -1, 0, 0}, {0, 0, 0, 1}}});
    // Ry(90): z -> x, x -> -z.
    expectMatrix(rotateMatrix(1, 90.0), {{{0, 0, -1, 0}, {0, 1, 0, 0}, {1, 0, 0, 0}, {0, 0, 0, 1}}});
    // Rz(90): x -> y, y -> -x.
    expectMatrix(rotateMatrix(2, 90.0), {{{0, 1, 0, 0}, {-1, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}});
    // Rz(30): x -> (cos 30, sin 30).
    const double c = std::sqrt(3.0) / 2.0, s = 0.5;
    expectMatrix(rotateMatrix(2, 30.0), {{{c, s, 0, 0}, {-s, c, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}});
}

TEST(XformOp, ThreeAxisRotationsApplyTheirAxesInNameOrder) {
    // rotateXYZ (90, 0, 90): X first, then Z. x -> x -> y; y -> z -> z; z -> -y -> x.
    expectMatrix(rotateEulerMatrix(XformOpType::RotateXYZ, {90, 0, 90}),
                 {{{0, 1, 0, 0}, {0, 0, 1, 0}, {1, 0, 0, 0}, {0, 0, 0, 1}}});
    // rotateZYX (90, 0, 90): Z first, then X. x -> y -> z; y -> -x -> -x; z -> z -> -y.
    expectMatrix(rotateEulerMatrix(XformOpType::RotateZYX, {90, 0, 90}),
                 {{{0, 0, 1, 0}, {-1, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, 0, 1}}});
    // rotateYXZ (90, 90, 0): Y first, then X. x -> -z -> y; y -> y -> z; z -> x -> x.
    expectMatrix(rotateEulerMatrix(XformOpType::RotateYXZ, {90, 90, 0}),
                 {{{0, 1, 0, 0}, {0, 0, 1, 0}, {1, 0, 0, 0}, {0, 0, 0, 1}}});
}

TEST(XformOp, OrientIsTheQuaternionsRotation) {
    // 90 degrees about +Y: q = (cos 45, 0, sin 45, 0): z -> x, x -> -z.
    const double h = std::sqrt(0.5);
    expectMatrix(orientMatrix(h, {0, h, 0}), {{{0, 0, -1, 0}, {0, 1, 0, 0}, {1, 0, 0, 0}, {0, 0, 0, 1}}});
    // Not normalized: the same rotation.
    expectMatrix(orientMatrix(2 * h, {0, 2 * h, 0}), {{{0, 0, -1, 0}, {0, 1, 0, 0}, {1, 0, 0, 0}, {0, 0, 0, 1}}});
    EXPECT_THROW(orientMatrix(0, {0, 0, 0}), Error);
}

TEST(XformOp, OpNamesMayCarrySuffixes) {
    EXPECT_EQ(parseXformOpName("xformOp:rotateXYZ"), XformOpType::RotateXYZ);
    EXPECT_EQ(parseXformOpName("xformOp:translate:pivot"), XformOpType::Translate);
    EXPECT_EQ(parseXformOpName("xformOp:rotateX:orientToStageUpAxis"), XformOpType::RotateX);
    EXPECT_EQ(parseXformOpName("xformOp:shear"), std::nullopt);
    EXPECT_EQ(parseXformOpName("xformOp:translate:"), std::nullopt);
    EXPECT_EQ(parseXformOpName("translate"), std::nullopt);
}

TEST(XformOp, OrderEntriesMayInvertAnOp) {
    const std::optional<XformOpOrderEntry> pivot = parseXformOpOrderEntry("!invert!xformOp:translate:pivot");
    ASSERT_TRUE(pivot);
    EXPECT_EQ(pivot->opName, "xformOp:translate:pivot");
    EXPECT_EQ(pivot->type, XformOpType::Translate);
    EXPECT_TRUE(pivot->inverted);
    const std::optional<XformOpOrderEntry> scale = parseXformOpOrderEntry("xformOp:scale");
    ASSERT_TRUE(scale);
    EXPECT_FALSE(scale->inverted);
    EXPECT_EQ(parseXformOpOrderEntry("!invert!xformOp:shear"), std::nullopt);
    EXPECT_EQ(parseXformOpOrderEntry(kResetXformStack), std::nullopt);
}

TEST(XformOp, AnInvertedEntryIsTheInverseOfItsOp) {
    const Value offset = Value::make<types::Double3>({1, 2, 3});
    expectMatrix(xformOpMatrix(*parseXformOpOrderEntry("!invert!xformOp:translate"), offset),
                 {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {-1, -2, -3, 1}}});
    const Value quarterTurn = Value::make<types::Float>(90.0f);
    // Rz(-90): x -> -y, y -> x.
    expectMatrix(xformOpMatrix(*parseXformOpOrderEntry("!invert!xformOp:rotateZ"), quarterTurn),
                 {{{0, -1, 0, 0}, {1, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}});
    const Value flat = Value::make<types::Float3>({0, 1, 1});
    try {
        xformOpMatrix(*parseXformOpOrderEntry("!invert!xformOp:scale"), flat);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "is singular and cannot be inverted (!invert!xformOp:scale)");
    }
}

}  // namespace
}  // namespace opal::usda
