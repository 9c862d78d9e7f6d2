#include "bake/face_orientation.h"

#include "tests/bake/test_meshes.h"

#include <gtest/gtest.h>

namespace opal {
namespace {

void reverseFace(ControlMesh& mesh, std::size_t face) {  // quads only
    std::reverse(mesh.faceVertexIndices.begin() + 4 * face + 1, mesh.faceVertexIndices.begin() + 4 * face + 4);
}

FaceOrientation orient(const ControlMesh& mesh) {
    MeshEdges edges(mesh.faceVertexCounts, mesh.faceVertexIndices);
    return orientFacesConsistently(edges, mesh.faceVertexCounts);
}

TEST(FaceOrientation, EnclosedVolumeMatchesClosedForms) {
    ControlMesh cube = test::cube(1.0f);  // side 2
    EXPECT_DOUBLE_EQ(enclosedVolume(cube.positions, cube.faceVertexCounts, cube.faceVertexIndices), 8.0);
    ControlMesh octa = test::octahedron(1.5f);  // (4/3) r^3
    EXPECT_NEAR(enclosedVolume(octa.positions, octa.faceVertexCounts, octa.faceVertexIndices), 4.5, 1e-6);
    for (std::size_t f = 0; f < 6; ++f) reverseFace(cube, f);
    EXPECT_DOUBLE_EQ(enclosedVolume(cube.positions, cube.faceVertexCounts, cube.faceVertexIndices), -8.0);
}

TEST(FaceOrientation, ReversesTheMinorityOfEachComponent) {
    ControlMesh mesh = test::cube();
    reverseFace(mesh, 1);
    reverseFace(mesh, 4);
    FaceOrientation o = orient(mesh);
    EXPECT_FALSE(o.conflict);
    EXPECT_EQ(o.reversed, (std::vector<char>{0, 1, 0, 0, 1, 0}));

    // Four of six reversed: reversing the other two is the smaller change.
    for (std::size_t f : {0, 2}) reverseFace(mesh, f);
    o = orient(mesh);
    EXPECT_EQ(o.reversed, (std::vector<char>{0, 0, 0, 1, 0, 1}));
}

TEST(FaceOrientation, ComponentsAreOrientedSeparately) {
    ControlMesh two = test::cube();
    ControlMesh second = test::cube();
    for (Imath::V3f p : second.positions) two.positions.push_back(p + Imath::V3f(3, 0, 0));
    for (std::size_t f = 0; f < 6; ++f) {
        const std::int32_t* c = &second.faceVertexIndices[4 * f];
        test::addFace(two, {c[0] + 8, c[1] + 8, c[2] + 8, c[3] + 8});
    }
    reverseFace(two, 7);
    FaceOrientation o = orient(two);
    EXPECT_EQ(o.reversed, (std::vector<char>{0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0}));
}

}  // namespace
}  // namespace opal
