#include "bake/mesh_validation.h"

#include "schema/error.h"
#include "tests/bake/test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace opal {
namespace {

using test::addFace;

// The error message validateAndRepair throws, or "" if it does not.
std::string errorOf(ControlMesh mesh, const RepairOptions& options = {}) {
    try {
        validateAndRepair(mesh, options);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Each face as its list of corner positions, to compare meshes whose vertex numbering
// differs.
std::vector<std::vector<Imath::V3f>> facePositions(const ControlMesh& mesh) {
    std::vector<std::vector<Imath::V3f>> faces;
    std::size_t start = 0;
    for (std::int32_t n : mesh.faceVertexCounts) {
        std::vector<Imath::V3f> face;
        for (std::int32_t c = 0; c < n; ++c) face.push_back(mesh.positions[mesh.faceVertexIndices[start + c]]);
        faces.push_back(face);
        start += std::size_t(n);
    }
    return faces;
}

TEST(MeshValidation, CleanMeshesPassUnchanged) {
    for (ControlMesh mesh : {test::cube(), test::octahedron(), test::icosahedron(), test::icosphere(2),
                             test::torus(1.0f, 0.3f, 12, 8), test::planeGrid(3)}) {
        ControlMesh before = mesh;
        ValidationReport report = validateAndRepair(mesh);
        EXPECT_TRUE(report.warnings.empty()) << mesh.source << ": " << report.warnings.front();
        EXPECT_EQ(mesh.positions, before.positions) << mesh.source;
        EXPECT_EQ(mesh.faceVertexIndices, before.faceVertexIndices) << mesh.source;
    }
}

TEST(MeshValidation, RefusesEmptyMesh) {
    ControlMesh mesh;
    mesh.source = "empty.obj";
    std::string error = errorOf(mesh);
    EXPECT_TRUE(contains(error, "empty.obj: the mesh is empty (0 vertices, 0 faces)")) << error;
}

TEST(MeshValidation, RefusesNonFinitePositionNamingTheVertex) {
    ControlMesh mesh = test::cube();
    mesh.positions[3].y = std::numeric_limits<float>::quiet_NaN();
    mesh.positions[6].z = std::numeric_limits<float>::infinity();
    std::string error = errorOf(mesh);
    EXPECT_TRUE(contains(error, "cube: vertex 3 (0.5, nan, -0.5) is not finite (2 non-finite vertices in total)"))
        << error;
}

TEST(MeshValidation, RefusesOutOfRangeIndexNamingFaceAndCorner) {
    ControlMesh mesh = test::cube();
    mesh.faceVertexIndices[9] = 99;  // face 2, corner 1
    std::string error = errorOf(mesh);
    EXPECT_TRUE(contains(error, "face 2, corner 1 refers to vertex 99 but there are 8 vertices (1 out-of-range index"))
        << error;
    mesh.faceVertexIndices[9] = -1;
    EXPECT_TRUE(contains(errorOf(mesh), "refers to vertex -1")) << errorOf(mesh);
}

TEST(MeshValidation, RefusesFacesWithFewerThanThreeCorners) {
    ControlMesh mesh = test::cube();
    addFace(mesh, {0, 7});
    EXPECT_TRUE(contains(errorOf(mesh), "face 6 has 2 corners; a face needs at least 3")) << errorOf(mesh);
}

TEST(MeshValidation, RefusesCornerCountMismatch) {
    ControlMesh mesh = test::cube();
    mesh.faceVertexIndices.pop_back();
    EXPECT_TRUE(contains(errorOf(mesh), "the face sizes add up to 24 corners but there are 23")) << errorOf(mesh);
}

TEST(MeshValidation, RefusesNonManifoldEdgeNamingItsFaces) {
    // Three quads hinged on the edge between vertices 0 and 1, like the pages of a book.
    ControlMesh mesh;
    mesh.source = "book";
    mesh.positions = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, 1, 0}, {0, 0, 1}, {0, 1, 1}};
    addFace(mesh, {0, 2, 3, 1});
    addFace(mesh, {1, 5, 4, 0});
    addFace(mesh, {0, 1, 7, 6});
    std::string error = errorOf(mesh);
    EXPECT_TRUE(contains(error, "book: non-manifold edge between vertex 0 (0, 0, 0) and vertex 1 (0, 1, 0): used by 3 "
                                "faces (0, 1, 2); 1 non-manifold edge in total"))
        << error;
}

TEST(MeshValidation, RefusesInconsistentWindingByDefault) {
    ControlMesh mesh = test::cube();
    std::reverse(mesh.faceVertexIndices.begin() + 13, mesh.faceVertexIndices.begin() + 16);  // face 3
    std::string error = errorOf(mesh);
    EXPECT_TRUE(contains(error, "cube: inconsistent winding: faces ")) << error;
    EXPECT_TRUE(contains(error, "in the same direction (4 such edges); enable winding repair")) << error;
}

TEST(MeshValidation, FixWindingReorientsTheMinority) {
    ControlMesh original = test::cube();
    ControlMesh mesh = original;
    std::reverse(mesh.faceVertexIndices.begin() + 13, mesh.faceVertexIndices.begin() + 16);  // face 3
    ValidationReport report = validateAndRepair(mesh, {.fixWinding = true});
    ASSERT_EQ(report.warnings.size(), 1u);
    EXPECT_EQ(report.warnings[0],
              "reversed the winding of 1 face to agree with their neighbours (4 edges were walked the same way by both "
              "faces)");
    EXPECT_EQ(mesh.faceVertexIndices, original.faceVertexIndices);
}

TEST(MeshValidation, RefusesNonOrientableSurface) {
    // A Moebius strip of 6 quads: the last quad joins the first with a half twist.
    ControlMesh mesh;
    mesh.source = "moebius";
    const int n = 6;
    for (int i = 0; i < n; ++i) {
        double a = 2 * std::numbers::pi * i / n, twist = a / 2;
        Imath::V3f centre(float(std::cos(a)), float(std::sin(a)), 0.0f);
        Imath::V3f radial(float(std::cos(a)), float(std::sin(a)), 0.0f);
        Imath::V3f across = radial * float(0.3 * std::cos(twist)) + Imath::V3f(0, 0, float(0.3 * std::sin(twist)));
        mesh.positions.push_back(centre - across);
        mesh.positions.push_back(centre + across);
    }
    for (int i = 0; i + 1 < n; ++i) addFace(mesh, {2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1});
    addFace(mesh, {2 * (n - 1), 1, 0, 2 * (n - 1) + 1});  // the twist: inner joins outer
    std::string error = errorOf(mesh, {.fixWinding = true});
    EXPECT_TRUE(contains(error, "moebius: the surface is not orientable")) << error;
}

TEST(MeshValidation, ReversesInsideOutClosedMesh) {
    ControlMesh mesh = test::octahedron();
    ControlMesh original = mesh;
    for (std::size_t f = 0; f < mesh.faceCount(); ++f) std::swap(mesh.faceVertexIndices[3 * f + 1], mesh.faceVertexIndices[3 * f + 2]);
    ValidationReport report = validateAndRepair(mesh);
    ASSERT_EQ(report.warnings.size(), 1u);
    EXPECT_EQ(report.warnings[0], "reversed all 8 faces: the closed mesh was inside out (its faces enclosed a negative volume)");
    EXPECT_EQ(mesh.faceVertexIndices, original.faceVertexIndices);
}

TEST(MeshValidation, LeavesOpenMeshOrientationAlone) {
    ControlMesh mesh = test::planeGrid(2);
    for (std::size_t f = 0; f < mesh.faceCount(); ++f) std::reverse(mesh.faceVertexIndices.begin() + 4 * f + 1, mesh.faceVertexIndices.begin() + 4 * f + 4);
    ControlMesh flipped = mesh;
    EXPECT_TRUE(validateAndRepair(mesh).warnings.empty());
    EXPECT_EQ(mesh.faceVertexIndices, flipped.faceVertexIndices);
}

// Every face with its own 4 vertices, as STL files and seam-split importers produce.
ControlMesh unweldedCube() {
    ControlMesh welded = test::cube();
    ControlMesh mesh;
    mesh.source = "cube-soup";
    for (std::int32_t v : welded.faceVertexIndices) {
        mesh.faceVertexIndices.push_back(std::int32_t(mesh.positions.size()));
        mesh.positions.push_back(welded.positions[v]);
    }
    mesh.faceVertexCounts = welded.faceVertexCounts;
    return mesh;
}

TEST(MeshValidation, WeldsIdenticalPositions) {
    ControlMesh mesh = unweldedCube();
    ValidationReport report = validateAndRepair(mesh);
    ASSERT_EQ(report.warnings.size(), 1u);
    EXPECT_EQ(report.warnings[0], "welded 16 vertices with identical positions");
    EXPECT_EQ(mesh.positions.size(), 8u);
    EXPECT_EQ(facePositions(mesh), facePositions(test::cube()));
}

TEST(MeshValidation, WeldsWithinToleranceOnlyWhenAsked) {
    ControlMesh mesh = unweldedCube();
    mesh.positions[5] += Imath::V3f(1e-5f, 0, 0);  // a near miss, 1e-5 of a unit cube
    ControlMesh exactOnly = mesh;
    ValidationReport report = validateAndRepair(exactOnly);
    EXPECT_EQ(report.warnings[0], "welded 15 vertices with identical positions");
    EXPECT_EQ(exactOnly.positions.size(), 9u);

    report = validateAndRepair(mesh, {.weldTolerance = 1e-4});
    ASSERT_EQ(report.warnings.size(), 2u);
    EXPECT_TRUE(contains(report.warnings[1], "welded 1 vertex closer than")) << report.warnings[1];
    EXPECT_EQ(mesh.positions.size(), 8u);
}

TEST(MeshValidation, CollapsesRepeatedCornersAndDropsDegenerateFaces) {
    ControlMesh mesh = test::cube();
    mesh.faceVertexIndices.erase(mesh.faceVertexIndices.begin(), mesh.faceVertexIndices.begin() + 4);
    mesh.faceVertexCounts.erase(mesh.faceVertexCounts.begin());
    // The -z face as two faces, one with a doubled corner: (0 2 2 3) and (0 3 1).
    addFace(mesh, {0, 2, 2, 3});
    addFace(mesh, {0, 3, 1});
    addFace(mesh, {4, 5, 4, 6});  // a vertex used twice, not in a row: dropped
    addFace(mesh, {7, 7, 7});     // one distinct vertex: dropped
    ValidationReport report = validateAndRepair(mesh);
    ASSERT_EQ(report.warnings.size(), 2u);
    EXPECT_EQ(report.warnings[0], "removed 1 repeated corner");
    EXPECT_EQ(report.warnings[1], "dropped 2 degenerate faces (fewer than 3 distinct vertices, or a vertex used twice)");
    EXPECT_EQ(mesh.faceCount(), 7u);
    EXPECT_EQ(mesh.faceVertexCounts[5], 3);
}

TEST(MeshValidation, DropsZeroAreaFacesAndTheirOrphans) {
    ControlMesh mesh = test::cube();
    // A sliver along the edge from vertex 0 to vertex 1 through its midpoint (vertex 8).
    mesh.positions.push_back({0.0f, -0.5f, -0.5f});
    addFace(mesh, {0, 8, 1});
    ValidationReport report = validateAndRepair(mesh);
    ASSERT_EQ(report.warnings.size(), 2u);
    EXPECT_EQ(report.warnings[0], "dropped 1 zero-area face");
    EXPECT_EQ(report.warnings[1], "dropped 1 unreferenced vertex");
    EXPECT_EQ(facePositions(mesh), facePositions(test::cube()));
}

TEST(MeshValidation, KeepsThinButRealFaces) {
    ControlMesh mesh;
    mesh.source = "sliver";
    mesh.positions = {{0, 0, 0}, {1000, 0, 0}, {500, 0.01f, 0}};  // height 1e-5 of its length
    addFace(mesh, {0, 1, 2});
    EXPECT_TRUE(validateAndRepair(mesh).warnings.empty());
    EXPECT_EQ(mesh.faceCount(), 1u);
}

TEST(MeshValidation, DropsUnreferencedVerticesAndRenumbers) {
    ControlMesh mesh = test::cube();
    mesh.positions.insert(mesh.positions.begin(), {{9, 9, 9}, {8, 8, 8}});
    for (std::int32_t& v : mesh.faceVertexIndices) v += 2;
    ValidationReport report = validateAndRepair(mesh);
    ASSERT_EQ(report.warnings.size(), 1u);
    EXPECT_EQ(report.warnings[0], "dropped 2 unreferenced vertices");
    EXPECT_EQ(mesh.positions, test::cube().positions);
    EXPECT_EQ(mesh.faceVertexIndices, test::cube().faceVertexIndices);
}

TEST(MeshValidation, KeepsFaceVaryingUvsInStepWithFaces) {
    ControlMesh mesh = test::cube();
    for (std::size_t c = 0; c < mesh.faceVertexIndices.size(); ++c) {
        mesh.uvIndices.push_back(std::int32_t(c));
        mesh.uvs.emplace_back(float(c), 0.0f);
    }
    mesh.positions.push_back({0.0f, -0.5f, -0.5f});
    addFace(mesh, {0, 8, 1});  // zero area: dropped with its UVs
    mesh.uvIndices.insert(mesh.uvIndices.end(), {0, 1, 2});
    for (std::size_t f = 0; f < 6; ++f) {  // inside out, UVs following their corners
        std::reverse(mesh.faceVertexIndices.begin() + 4 * f + 1, mesh.faceVertexIndices.begin() + 4 * f + 4);
        std::reverse(mesh.uvIndices.begin() + 4 * f + 1, mesh.uvIndices.begin() + 4 * f + 4);
    }
    validateAndRepair(mesh);  // drops the sliver, then un-reverses the inside-out cube
    ASSERT_EQ(mesh.uvIndices.size(), mesh.faceVertexIndices.size());
    EXPECT_EQ(mesh.faceVertexIndices, test::cube().faceVertexIndices);
    for (std::size_t c = 0; c < mesh.uvIndices.size(); ++c) EXPECT_EQ(mesh.uvIndices[c], std::int32_t(c));
}

TEST(MeshValidation, RefusesBadUvIndices) {
    ControlMesh mesh = test::cube();
    mesh.uvs.resize(4);
    mesh.uvIndices.assign(mesh.faceVertexIndices.size(), 0);
    mesh.uvIndices[5] = 4;
    EXPECT_TRUE(contains(errorOf(mesh), "face 1, corner 1 refers to UV 4 but there are 4 UVs")) << errorOf(mesh);
}

TEST(MeshValidation, MessagesNameTheOriginalFaceNumbers) {
    ControlMesh mesh = test::cube();
    // Two degenerate faces first: the faces after them keep their input numbers in messages.
    ControlMesh withJunk;
    withJunk.source = "junk";
    withJunk.positions = mesh.positions;
    addFace(withJunk, {0, 0, 0});
    addFace(withJunk, {1, 1, 1});
    withJunk.faceVertexCounts.insert(withJunk.faceVertexCounts.end(), mesh.faceVertexCounts.begin(), mesh.faceVertexCounts.end());
    withJunk.faceVertexIndices.insert(withJunk.faceVertexIndices.end(), mesh.faceVertexIndices.begin(), mesh.faceVertexIndices.end());
    addFace(withJunk, {0, 1, 2});  // a third face on edge (0, 1)... and (0, 2)
    std::string error = errorOf(withJunk);
    EXPECT_TRUE(contains(error, "used by 3 faces (2, 4, 8)")) << error;
}

}  // namespace
}  // namespace opal
