// The scene reader's xformOp composition against matrices computed by hand (row vectors,
// p' = p M, as USD and Imath): op order, pivots, !resetXformStack! and the errors that name
// the attribute. The ops themselves: tests/usd/xform_op_test.cpp.
#include "examples/scene/xformable.h"
#include "schema/usd/usda_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace opal::scene {
namespace {

using Rows = std::array<std::array<double, 4>, 4>;

void expectMatrix(const Imath::M44d& actual, const Rows& expected) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(actual[r][c], expected[r][c], 1e-12) << "row " << r << ", column " << c;
}


void expectPoint(const Imath::V3d& actual, const Imath::V3d& expected) {
    EXPECT_NEAR(actual.x, expected.x, 1e-12);
    EXPECT_NEAR(actual.y, expected.y, 1e-12);
    EXPECT_NEAR(actual.z, expected.z, 1e-12);
}

// The local transform of prim /A whose body is `body`.
LocalTransform localOf(const std::string& body) {
    const usda::Layer layer = usda::readUsda("#usda 1.0\ndef Xform \"A\"\n{\n" + body + "}\n", "xf.usda");
    PrimReader reader(layer.prim("/A"), "/A");
    LocalTransform local = readLocalTransform(reader);
    reader.finish();
    return local;
}

std::string errorOf(const std::string& body) {
    try {
        localOf(body);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

TEST(Xformable, OrderListsOpsOutermostFirst) {
    // translate (1, 2, 3), rotateZ 90, scale 2: a point is scaled, rotated, then moved.
    // By hand: S Rz T = [[0, 2, 0], [-2, 0, 0], [0, 0, 2]] with translation (1, 2, 3).
    const LocalTransform local = localOf(
        "    double3 xformOp:translate = (1, 2, 3)\n"
        "    float xformOp:rotateZ = 90\n"
        "    float3 xformOp:scale = (2, 2, 2)\n"
        "    uniform token[] xformOpOrder = [\"xformOp:translate\", \"xformOp:rotateZ\", \"xformOp:scale\"]\n");
    expectMatrix(local.matrix, {{{0, 2, 0, 0}, {-2, 0, 0, 0}, {0, 0, 2, 0}, {1, 2, 3, 1}}});
    expectPoint(Imath::V3d(1, 0, 0) * local.matrix, {1, 4, 3});
    EXPECT_FALSE(local.resetsXformStack);
}

TEST(Xformable, ReversedOrderMovesFirst) {
    // scale, rotateZ, translate listed: translate first, then rotate, then scale.
    const LocalTransform local = localOf(
        "    double3 xformOp:translate = (1, 2, 3)\n"
        "    float xformOp:rotateZ = 90\n"
        "    float3 xformOp:scale = (2, 2, 2)\n"
        "    uniform token[] xformOpOrder = [\"xformOp:scale\", \"xformOp:rotateZ\", \"xformOp:translate\"]\n");
    // (1, 0, 0) -> (2, 2, 3) -> (-2, 2, 3) -> (-4, 4, 6).
    expectPoint(Imath::V3d(1, 0, 0) * local.matrix, {-4, 4, 6});
}

TEST(Xformable, TransformOpIsTheMatrixAsWritten) {
    const LocalTransform local = localOf(
        "    matrix4d xformOp:transform = ( (0, 0, -1, 0), (0, 1, 0, 0), (1, 0, 0, 0), (5, 6, 7, 1) )\n"
        "    uniform token[] xformOpOrder = [\"xformOp:transform\"]\n");
    expectMatrix(local.matrix, {{{0, 0, -1, 0}, {0, 1, 0, 0}, {1, 0, 0, 0}, {5, 6, 7, 1}}});
}

TEST(Xformable, InvertedPivotRotatesAboutThePivot) {
    const LocalTransform local = localOf(
        "    double3 xformOp:translate:pivot = (1, 0, 0)\n"
        "    float xformOp:rotateY = 90\n"
        "    uniform token[] xformOpOrder = [\"xformOp:translate:pivot\", \"xformOp:rotateY\", "
        "\"!invert!xformOp:translate:pivot\"]\n");
    expectPoint(Imath::V3d(1, 0, 0) * local.matrix, {1, 0, 0});   // the pivot stays
    expectPoint(Imath::V3d(2, 0, 0) * local.matrix, {1, 0, -1});  // (1,0,0) about it -> (0,0,-1)
}

TEST(Xformable, ResetXformStackIsReported) {
    const LocalTransform local = localOf(
        "    double3 xformOp:translate = (1, 0, 0)\n"
        "    uniform token[] xformOpOrder = [\"!resetXformStack!\", \"xformOp:translate\"]\n");
    EXPECT_TRUE(local.resetsXformStack);
    expectPoint(Imath::V3d(0, 0, 0) * local.matrix, {1, 0, 0});
}

TEST(Xformable, NoOrderIsIdentity) { expectMatrix(localOf("").matrix, {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}); }

TEST(Xformable, ErrorsNameTheAttribute) {
    EXPECT_EQ(errorOf("    double3 xformOp:translate = (1, 2, 3)\n"),
              "xf.usda:4:5: Xform </A>: 'xformOp:translate' is not listed in xformOpOrder (USD would ignore it)");
    EXPECT_EQ(errorOf("    uniform token[] xformOpOrder = [\"xformOp:translate\"]\n"),
              "xf.usda:4:5: Xform </A>: attribute 'xformOpOrder' lists 'xformOp:translate', which the prim does not "
              "author with a value");
    EXPECT_EQ(errorOf("    double xformOp:translate = 1\n    uniform token[] xformOpOrder = [\"xformOp:translate\"]\n"),
              "xf.usda:4:5: Xform </A>: attribute 'xformOp:translate' has type double, expected float3 or double3");
    EXPECT_EQ(errorOf("    uniform token[] xformOpOrder = [\"xformOp:shear\"]\n"),
              "xf.usda:4:5: Xform </A>: attribute 'xformOpOrder' lists 'xformOp:shear', which is not an xformOp name "
              "(see examples/SCENES.md)");
    EXPECT_EQ(errorOf("    float xformOp:rotateX = 1\n"
                      "    uniform token[] xformOpOrder = [\"xformOp:rotateX\", \"xformOp:rotateX\"]\n"),
              "xf.usda:5:5: Xform </A>: attribute 'xformOpOrder' lists 'xformOp:rotateX' twice");
    EXPECT_EQ(errorOf("    float3 xformOp:scale = (0, 1, 1)\n"
                      "    uniform token[] xformOpOrder = [\"!invert!xformOp:scale\"]\n"),
              "xf.usda:4:5: Xform </A>: attribute 'xformOp:scale' is singular and cannot be inverted "
              "(!invert!xformOp:scale)");
}

}  // namespace
}  // namespace opal::scene
