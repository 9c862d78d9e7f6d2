#include "bake/subdivision.h"

#include "schema/error.h"
#include "tests/bake/test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace opal {
namespace {

float distanceToNearestPoint(const RenderMesh& mesh, const Imath::V3f& target) {
    float best = INFINITY;
    for (const Imath::V3f& p : mesh.points) best = std::min(best, (p - target).length());
    return best;
}

std::size_t indexOfNearestPoint(const RenderMesh& mesh, const Imath::V3f& target) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < mesh.points.size(); ++i) {
        if ((mesh.points[i] - target).length2() < (mesh.points[best] - target).length2()) best = i;
    }
    return best;
}

void expectUnitOutwardNormals(const RenderMesh& mesh, const Imath::V3f& centre, float minCosine) {
    ASSERT_EQ(mesh.normals.size(), mesh.points.size());
    for (std::size_t v = 0; v < mesh.points.size(); ++v) {
        EXPECT_NEAR(mesh.normals[v].length(), 1.0f, 1e-5f) << "vertex " << v;
        Imath::V3f radial = (mesh.points[v] - centre).normalized();
        EXPECT_GT(mesh.normals[v].dot(radial), minCosine) << "vertex " << v;
    }
}

TEST(Subdivision, CubeCatmullClarkLevel3Has386VerticesAnd384Quads) {
    RenderMesh mesh = subdivide(test::cube(), {SubdivisionScheme::CatmullClark, 3});
    EXPECT_EQ(mesh.points.size(), 386u);
    EXPECT_EQ(mesh.faceVertexCounts.size(), 384u);
    EXPECT_TRUE(std::all_of(mesh.faceVertexCounts.begin(), mesh.faceVertexCounts.end(), [](int n) { return n == 4; }));
    EXPECT_EQ(mesh.faceVertexIndices.size(), 4u * 384u);
}

// Halstead et al. 1993: the Catmull-Clark limit of a valence-n vertex v is
// (n^2 v + 4 sum(edge neighbours) + sum(face-diagonal vertices)) / (n (n + 5)). For a corner
// of the cube [-0.5, 0.5]^3: (9 * 0.5 + 4 * 0.5 - 0.5) / 24 = 0.25 per coordinate.
TEST(Subdivision, CubeCornersReachTheirClosedFormLimit) {
    for (int level : {0, 2}) {
        RenderMesh mesh = subdivide(test::cube(), {SubdivisionScheme::CatmullClark, level});
        for (int corner = 0; corner < 8; ++corner) {
            Imath::V3f expected(corner & 1 ? 0.25f : -0.25f, corner & 2 ? 0.25f : -0.25f, corner & 4 ? 0.25f : -0.25f);
            std::size_t v = indexOfNearestPoint(mesh, expected);
            EXPECT_LT((mesh.points[v] - expected).length(), 1e-6f) << "level " << level << " corner " << corner;
            // By symmetry the limit normal at a corner is along the diagonal.
            EXPECT_GT(mesh.normals[v].dot(expected.normalized()), 1.0f - 1e-5f) << "level " << level;
        }
    }
}

TEST(Subdivision, CubeLimitNormalsAreUnitAndOutward) {
    RenderMesh mesh = subdivide(test::cube(), {SubdivisionScheme::CatmullClark, 3});
    expectUnitOutwardNormals(mesh, Imath::V3f(0.0f), 0.3f);
}

// Loop's limit mask (as OpenSubdiv implements it): v_inf = (1 - n chi) v + chi sum(neighbours),
// chi = 1 / (n + 3 / (8 gamma)), gamma = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n.
TEST(Subdivision, IcosahedronLoopMatchesClosedFormCountsAndVertexLimits) {
    ControlMesh ico = test::icosahedron();
    for (int level : {1, 3}) {
        RenderMesh mesh = subdivide(ico, {SubdivisionScheme::Loop, level});
        std::size_t faces = 20u << (2 * level);
        EXPECT_EQ(mesh.faceVertexCounts.size(), faces);
        EXPECT_EQ(mesh.points.size(), 2 + faces / 2);  // Euler: V - E + F = 2 with E = 3F/2
        EXPECT_TRUE(std::all_of(mesh.faceVertexCounts.begin(), mesh.faceVertexCounts.end(), [](int n) { return n == 3; }));

        const double n = 5.0;
        double b = 3.0 / 8.0 + std::cos(2 * std::numbers::pi / n) / 4.0;
        double gamma = (5.0 / 8.0 - b * b) / n;
        double chi = 1.0 / (n + 3.0 / (8.0 * gamma));
        for (std::size_t v = 0; v < ico.positions.size(); ++v) {
            Imath::V3d sum(0.0);
            for (std::size_t f = 0; f < ico.faceCount(); ++f) {  // each neighbour appears in two faces
                for (int c = 0; c < 3; ++c) {
                    if (ico.faceVertexIndices[3 * f + c] == std::int32_t(v)) {
                        sum += Imath::V3d(ico.positions[ico.faceVertexIndices[3 * f + (c + 1) % 3]]);
                    }
                }
            }
            Imath::V3d limit = (1.0 - n * chi) * Imath::V3d(ico.positions[v]) + chi * sum;
            EXPECT_LT(distanceToNearestPoint(mesh, Imath::V3f(limit)), 1e-5f) << "level " << level << " vertex " << v;
        }
    }
}

TEST(Subdivision, LoopSphereLimitStaysInsideItsCageWithUnitOutwardNormals) {
    // The limit surface lies in the convex hull of the cage (non-negative weights), so
    // within the unit sphere; it shrinks to about 0.708 at the 12 valence-5 vertices (see
    // above) and a little more between them.
    RenderMesh mesh = subdivide(test::icosahedron(), {SubdivisionScheme::Loop, 3});
    float minRadius = INFINITY, maxRadius = 0.0f;
    for (const Imath::V3f& p : mesh.points) {
        minRadius = std::min(minRadius, p.length());
        maxRadius = std::max(maxRadius, p.length());
    }
    EXPECT_LE(maxRadius, 1.0f);
    EXPECT_GT(minRadius, 0.69f);
    EXPECT_LT(maxRadius - minRadius, 0.08f);  // round: the limit is a smooth near-sphere
    expectUnitOutwardNormals(mesh, Imath::V3f(0.0f), 0.95f);
}

TEST(Subdivision, CatmullClarkOfAFineSphereCageShrinksLittle) {
    // A 320-triangle sphere cage: Catmull-Clark quads; the limit lies inside the cage's
    // convex hull and, the cage being fine, within 3% of its radius.
    RenderMesh mesh = subdivide(test::icosphere(2, 2.0f), {SubdivisionScheme::CatmullClark, 2});
    EXPECT_TRUE(std::all_of(mesh.faceVertexCounts.begin(), mesh.faceVertexCounts.end(), [](int n) { return n == 4; }));
    for (const Imath::V3f& p : mesh.points) {
        EXPECT_LE(p.length(), 2.0f);
        EXPECT_GT(p.length(), 2.0f * 0.97f);
    }
    expectUnitOutwardNormals(mesh, Imath::V3f(0.0f), 0.99f);
}

TEST(Subdivision, TorusNormalsPointAwayFromTheCoreCircle) {
    RenderMesh mesh = subdivide(test::torus(2.0f, 0.6f, 16, 8), {SubdivisionScheme::CatmullClark, 2});
    for (std::size_t v = 0; v < mesh.points.size(); ++v) {
        EXPECT_NEAR(mesh.normals[v].length(), 1.0f, 1e-5f);
        EXPECT_GT(mesh.normals[v].dot(test::torusNormal(mesh.points[v], 2.0f)), 0.95f) << "vertex " << v;
    }
}

TEST(Subdivision, OpenMeshKeepsCornersAndBoundaryEdges) {
    // Edge-and-corner boundary interpolation: the grid's corners stay put and its boundary
    // edges stay on the square's sides; the surface stays in the plane, normals +z.
    RenderMesh mesh = subdivide(test::planeGrid(3), {SubdivisionScheme::CatmullClark, 2});
    for (Imath::V3f corner : {Imath::V3f(0, 0, 0), Imath::V3f(1, 0, 0), Imath::V3f(0, 1, 0), Imath::V3f(1, 1, 0)}) {
        EXPECT_LT(distanceToNearestPoint(mesh, corner), 1e-6f);
    }
    float lowest = INFINITY, highest = -INFINITY;
    for (std::size_t v = 0; v < mesh.points.size(); ++v) {
        lowest = std::min({lowest, mesh.points[v].x, mesh.points[v].y});
        highest = std::max({highest, mesh.points[v].x, mesh.points[v].y});
        EXPECT_NEAR(mesh.points[v].z, 0.0f, 1e-6f);
        EXPECT_GT(mesh.normals[v].z, 0.9999f);
    }
    EXPECT_NEAR(lowest, 0.0f, 1e-6f);
    EXPECT_NEAR(highest, 1.0f, 1e-6f);
}

TEST(Subdivision, AutomaticSchemePicksLoopForTrianglesOnly) {
    EXPECT_EQ(resolveSubdivisionScheme(test::octahedron(), SubdivisionScheme::Automatic), SubdivisionScheme::Loop);
    EXPECT_EQ(resolveSubdivisionScheme(test::cube(), SubdivisionScheme::Automatic), SubdivisionScheme::CatmullClark);
    RenderMesh octa = subdivide(test::octahedron(), {SubdivisionScheme::Automatic, 1});
    EXPECT_EQ(octa.faceVertexCounts, std::vector<std::int32_t>(32, 3));
    RenderMesh quads = subdivide(test::octahedron(), {SubdivisionScheme::CatmullClark, 1});
    EXPECT_EQ(quads.faceVertexCounts, std::vector<std::int32_t>(24, 4));
}

TEST(Subdivision, LevelZeroKeepsTheControlTopology) {
    ControlMesh cube = test::cube();
    RenderMesh mesh = subdivide(cube, {SubdivisionScheme::CatmullClark, 0});
    EXPECT_EQ(mesh.faceVertexCounts, cube.faceVertexCounts);
    EXPECT_EQ(mesh.faceVertexIndices, cube.faceVertexIndices);
    EXPECT_EQ(mesh.points.size(), 8u);
}

TEST(Subdivision, RefusesForcedLoopOnQuads) {
    ControlMesh mesh = test::cube();
    mesh.source = "box.obj";
    try {
        subdivide(mesh, {SubdivisionScheme::Loop, 1});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(),
                     "box.obj: Loop subdivision needs triangles, but face 0 has 4 corners (6 non-triangular faces); use "
                     "catmullClark");
    }
}

TEST(Subdivision, RefusesBadLevels) {
    EXPECT_THROW(subdivide(test::cube(), {SubdivisionScheme::CatmullClark, -1}), Error);
    EXPECT_THROW(subdivide(test::cube(), {SubdivisionScheme::CatmullClark, 16}), Error);
    try {
        subdivide(test::icosphere(3), {SubdivisionScheme::Loop, 12});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("more than 32-bit indices hold"), std::string::npos) << e.what();
    }
}

TEST(Subdivision, AutomaticLevelIsTheCoarsestWithAsManyVerticesAsSamples) {
    // The refined vertex counts the rule is computed from, against OpenSubdiv's own
    // refinement: closed quads, closed triangles, a torus and an open grid (boundary edges).
    const std::pair<ControlMesh, SubdivisionScheme> meshes[] = {{test::cube(), SubdivisionScheme::CatmullClark},
                                                                {test::icosahedron(), SubdivisionScheme::Loop},
                                                                {test::torus(3.0f, 1.0f, 6, 4), SubdivisionScheme::CatmullClark},
                                                                {test::octahedron(), SubdivisionScheme::CatmullClark},
                                                                {test::planeGrid(3), SubdivisionScheme::CatmullClark}};
    for (const auto& [mesh, scheme] : meshes) {
        std::uint64_t previous = 0;
        for (int level = 0; level <= 4; ++level) {
            const std::uint64_t vertices = subdivide(mesh, {scheme, level}).points.size();
            if (level > 0) {
                EXPECT_EQ(automaticSubdivisionLevel(mesh, scheme, previous + 1), std::uint32_t(level)) << level;
            }
            EXPECT_EQ(automaticSubdivisionLevel(mesh, scheme, vertices), std::uint32_t(level)) << level;
            previous = vertices;
        }
    }
    EXPECT_EQ(automaticSubdivisionLevel(test::cube(), SubdivisionScheme::Automatic, 1), 0u);
    EXPECT_EQ(automaticSubdivisionLevel(test::cube(), SubdivisionScheme::Automatic, 1u << 30), kMaxAutomaticLevel);
}

TEST(Subdivision, ParsesSchemeNames) {
    EXPECT_EQ(parseSubdivisionScheme("auto"), SubdivisionScheme::Automatic);
    EXPECT_EQ(parseSubdivisionScheme("catmullClark"), SubdivisionScheme::CatmullClark);
    EXPECT_EQ(parseSubdivisionScheme("loop"), SubdivisionScheme::Loop);
    EXPECT_EQ(subdivisionSchemeName(SubdivisionScheme::CatmullClark), "catmullClark");
    EXPECT_THROW(parseSubdivisionScheme("bilinear"), Error);
}

}  // namespace
}  // namespace opal
