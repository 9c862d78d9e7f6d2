// The built-in candle and wick (bake/procedural_mesh.h), measured on the meshes themselves
// against the sizes the header documents: the pool's depth below the rim, the rim's
// crest as the highest point at every angle, closed and consistently wound surfaces
// enclosing a positive volume, and the wick standing in the pool (its base inside the
// wax, its tip above the pool surface found by casting a ray down onto the candle).
#include "bake/procedural_mesh.h"
#include "bake/subdivision.h"
#include "bake/mesh_validation.h"
#include "schema/error.h"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <Imath/ImathVec.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace opal {
namespace {

struct Polygons {
    std::span<const Imath::V3f> points;
    std::span<const std::int32_t> counts, indices;
};

Polygons polygonsOf(const ControlMesh& m) { return {m.positions, m.faceVertexCounts, m.faceVertexIndices}; }
Polygons polygonsOf(const RenderMesh& m) { return {m.points, m.faceVertexCounts, m.faceVertexIndices}; }

// Every directed edge a->b is walked by exactly one face and b->a by exactly one other:
// the surface is closed, two faces meet at every edge, and neighbours wind alike.
void expectClosedAndConsistentlyWound(const Polygons& mesh) {
    std::map<std::pair<std::int32_t, std::int32_t>, int> walked;
    std::size_t at = 0;
    for (std::int32_t n : mesh.counts) {
        for (std::int32_t c = 0; c < n; ++c) ++walked[{mesh.indices[at + c], mesh.indices[at + (c + 1) % n]}];
        at += std::size_t(n);
    }
    int bad = 0;
    for (const auto& [edge, count] : walked) {
        const auto reverse = walked.find({edge.second, edge.first});
        if (count != 1 || reverse == walked.end() || reverse->second != 1) ++bad;
    }
    EXPECT_EQ(bad, 0) << "directed edges not matched by exactly one opposite edge, of " << walked.size();
}

// The bake's own check finds nothing to weld, drop or reorient.
void expectNothingToRepair(ControlMesh mesh) {
    const ValidationReport report = validateAndRepair(mesh);
    EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();
}

// The triangles of the polygons, fanned from each face's first corner.
std::vector<std::array<Imath::V3d, 3>> triangles(const Polygons& mesh) {
    std::vector<std::array<Imath::V3d, 3>> out;
    std::size_t at = 0;
    for (std::int32_t n : mesh.counts) {
        for (std::int32_t c = 1; c + 1 < n; ++c)
            out.push_back({Imath::V3d(mesh.points[mesh.indices[at]]), Imath::V3d(mesh.points[mesh.indices[at + c]]),
                           Imath::V3d(mesh.points[mesh.indices[at + c + 1]])});
        at += std::size_t(n);
    }
    return out;
}

// Divergence theorem: positive for a closed surface wound counter-clockwise from outside.
double polygonVolume(const Polygons& mesh) {
    double volume = 0.0;
    for (const auto& t : triangles(mesh)) volume += t[0].dot(t[1].cross(t[2])) / 6.0;
    return volume;
}

// Distances t > 0 along the ray at which it crosses the triangles (Moller-Trumbore).
std::vector<double> crossings(const Polygons& mesh, const Imath::V3d& origin, const Imath::V3d& direction) {
    std::vector<double> hits;
    for (const auto& t : triangles(mesh)) {
        const Imath::V3d e1 = t[1] - t[0], e2 = t[2] - t[0], p = direction.cross(e2);
        const double det = e1.dot(p);
        if (std::abs(det) < 1e-12) continue;
        const Imath::V3d s = origin - t[0], q = s.cross(e1);
        const double u = s.dot(p) / det, v = direction.dot(q) / det, d = e2.dot(q) / det;
        if (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && d > 0.0) hits.push_back(d);
    }
    return hits;
}

// A point is inside a closed surface when a ray from it crosses the surface an odd number
// of times (the direction is skewed so that it passes no vertex or edge exactly).
bool inside(const Polygons& mesh, const Imath::V3d& point) {
    return crossings(mesh, point, Imath::V3d(0.123, 0.977, 0.171).normalized()).size() % 2 == 1;
}

// The highest point of the candle at each of its sectors: the vertices at angle
// 2 pi s / segments (within a hundredth of a degree), off the axis.
std::vector<Imath::V3f> highestPerSector(const ControlMesh& candle) {
    const int n = CandleSize::segments;
    std::vector<std::optional<Imath::V3f>> top(std::size_t(n), std::nullopt);
    for (const Imath::V3f& p : candle.positions) {
        if (std::hypot(p.x, p.z) < 1e-3f) continue;
        double phi = std::atan2(-double(p.z), double(p.x));
        if (phi < 0.0) phi += 2.0 * std::numbers::pi;
        const double sector = phi * n / (2.0 * std::numbers::pi);
        const int s = int(std::lround(sector)) % n;
        EXPECT_NEAR(sector, std::round(sector), 1e-4) << "a vertex between sectors";
        if (!top[s] || p.y > top[s]->y) top[s] = p;
    }
    std::vector<Imath::V3f> out;
    for (const auto& p : top) {
        EXPECT_TRUE(p.has_value());
        if (p) out.push_back(*p);
    }
    return out;
}

// The highest surface point on the axis: where a ray cast down the axis first meets the mesh.
double surfaceOnAxis(const Polygons& mesh) {
    const Imath::V3d origin(1e-4, 1000.0, 2e-4);
    const std::vector<double> hits = crossings(mesh, origin, Imath::V3d(0.0, -1.0, 0.0));
    EXPECT_FALSE(hits.empty());
    return origin.y - (hits.empty() ? 0.0 : *std::min_element(hits.begin(), hits.end()));
}

TEST(BuiltinCandle, TheRimCrestIsTheHighestPointAtEveryAngleAndWobblesAboutItsHeight) {
    const std::vector<Imath::V3f> crest = highestPerSector(makeCandle());
    ASSERT_EQ(crest.size(), std::size_t(CandleSize::segments));
    double mean = 0.0, low = 1e9, high = -1e9;
    for (const Imath::V3f& p : crest) {
        const float r = std::hypot(p.x, p.z);
        EXPECT_GE(r, CandleSize::rimInner - 1e-4f) << "the highest point at this angle is inside the rim";
        EXPECT_LE(r, CandleSize::radius + 1e-4f);
        mean += p.y / double(crest.size());
        low = std::min(low, double(p.y));
        high = std::max(high, double(p.y));
    }
    EXPECT_NEAR(mean, CandleSize::rimHeight, 1e-3);
    EXPECT_GE(low, CandleSize::rimHeight - CandleSize::rimWobble - 1e-4);
    EXPECT_LE(high, CandleSize::rimHeight + CandleSize::rimWobble + 1e-4);
    EXPECT_GT(high - low, CandleSize::rimWobble) << "the rim should be irregular, not a perfect circle";
}

TEST(BuiltinCandle, ThePoolCentreLiesItsDepthBelowTheRimAndIsTheLowestPointOfTheTop) {
    const ControlMesh candle = makeCandle();
    const double centre = surfaceOnAxis(polygonsOf(candle));
    EXPECT_NEAR(CandleSize::rimHeight - centre, CandleSize::poolDepth, 1e-4);
    EXPECT_GE(CandleSize::poolDepth, 3.0f) << "a pool a few millimetres below the rim";
    // Concave: every vertex inside the rim and above mid-height lies at or above the centre.
    for (const Imath::V3f& p : candle.positions)
        if (std::hypot(p.x, p.z) < CandleSize::rimInner && p.y > 40.0f) {
            EXPECT_GE(p.y, centre - 1e-4) << p;
        }
}

TEST(BuiltinCandle, IsClosedConsistentlyWoundAndEnclosesThePillar) {
    const ControlMesh candle = makeCandle();
    expectClosedAndConsistentlyWound(polygonsOf(candle));
    const double volume = polygonVolume(polygonsOf(candle));
    const double cylinder = std::numbers::pi * CandleSize::radius * CandleSize::radius;
    // Between a cylinder up to the pool's centre and one up to the rim.
    EXPECT_GT(volume, 0.95 * cylinder * CandleSize::poolCentre);
    EXPECT_LT(volume, cylinder * CandleSize::rimHeight);
    expectNothingToRepair(candle);
}

// The shape survives Catmull-Clark (what the bake renders): the limit surface's pool is
// still its depth below the rim (within 0.3 mm) and its rim still the highest point.
TEST(BuiltinCandle, CatmullClarkKeepsThePoolDepthAndTheRim) {
    ControlMesh control = makeCandle();
    validateAndRepair(control);
    const RenderMesh fine = subdivide(control, {SubdivisionScheme::CatmullClark, 3});
    expectClosedAndConsistentlyWound(polygonsOf(fine));
    double top = -1e9;
    for (const Imath::V3f& p : fine.points) top = std::max(top, double(p.y));
    EXPECT_NEAR(top, CandleSize::rimHeight, CandleSize::rimWobble + 0.1);
    EXPECT_NEAR(CandleSize::rimHeight - surfaceOnAxis(polygonsOf(fine)), CandleSize::poolDepth, 0.3);
}

TEST(BuiltinWick, IsClosedConsistentlyWoundAndStandsInThePool) {
    const ControlMesh wick = makeWick(), candle = makeCandle();
    expectClosedAndConsistentlyWound(polygonsOf(wick));
    EXPECT_GT(polygonVolume(polygonsOf(wick)), 0.0);
    expectNothingToRepair(wick);

    const auto lowest = std::min_element(wick.positions.begin(), wick.positions.end(),
                                         [](const Imath::V3f& a, const Imath::V3f& b) { return a.y < b.y; });
    const auto tip = std::max_element(wick.positions.begin(), wick.positions.end(),
                                      [](const Imath::V3f& a, const Imath::V3f& b) { return a.y < b.y; });
    const double pool = surfaceOnAxis(polygonsOf(candle));
    // The base is in the wax, the tip above the pool by the documented height.
    EXPECT_TRUE(inside(polygonsOf(candle), Imath::V3d(*lowest)));
    EXPECT_FALSE(inside(polygonsOf(candle), Imath::V3d(*tip)));
    EXPECT_NEAR(pool - lowest->y, WickSize::depth, 1e-4);
    EXPECT_NEAR(tip->y - pool, WickSize::height, 1e-4);
    // Bent: the tip is off the axis by the lean, toward +X; and all of it stays in the pool,
    // well inside the rim.
    EXPECT_NEAR(tip->x, WickSize::lean, 1e-4);
    EXPECT_NEAR(tip->z, 0.0f, 1e-4);
    for (const Imath::V3f& p : wick.positions) EXPECT_LT(std::hypot(p.x, p.z), CandleSize::rimInner / 4);
}

// The edge check itself: one face turned over, or one face taken away, fails it.
TEST(BuiltinMeshes, TheEdgeCheckCatchesAFlippedFaceAndAHole) {
    static ControlMesh flipped, open;
    flipped = makeWick();
    std::reverse(flipped.faceVertexIndices.begin(), flipped.faceVertexIndices.begin() + flipped.faceVertexCounts[0]);
    EXPECT_NONFATAL_FAILURE(expectClosedAndConsistentlyWound(polygonsOf(flipped)), "not matched");
    open = makeWick();
    open.faceVertexIndices.resize(open.faceVertexIndices.size() - std::size_t(open.faceVertexCounts.back()));
    open.faceVertexCounts.pop_back();
    EXPECT_NONFATAL_FAILURE(expectClosedAndConsistentlyWound(polygonsOf(open)), "not matched");
}

TEST(BuiltinMeshes, AreFoundByNameAndAnUnknownNameIsAnError) {
    EXPECT_EQ(builtinMesh("builtin:candle")->positions.size(), makeCandle().positions.size());
    EXPECT_EQ(builtinMesh("builtin:wick")->positions.size(), makeWick().positions.size());
    EXPECT_FALSE(builtinMesh("candle.obj").has_value());
    try {
        builtinMesh("builtin:lamp");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("'builtin:lamp'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("builtin:wick"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace opal
