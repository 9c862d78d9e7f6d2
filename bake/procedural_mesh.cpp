#include "bake/procedural_mesh.h"

#include "schema/error.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace opal {

namespace {

struct RevolutionBuilder {
    ControlMesh mesh;
    int segments;

    // Adds a ring (segments vertices) or a pole (one vertex); returns its first index.
    std::int32_t addRing(const Imath::V2f& p) {
        const auto first = std::int32_t(mesh.positions.size());
        if (p.x == 0.0f) {
            mesh.positions.emplace_back(0.0f, p.y, 0.0f);
            return first;
        }
        for (int s = 0; s < segments; ++s) {
            const double phi = 2.0 * std::numbers::pi * s / segments;
            mesh.positions.emplace_back(float(p.x * std::cos(phi)), p.y, float(-p.x * std::sin(phi)));
        }
        return first;
    }

    void addFace(std::initializer_list<std::int32_t> corners) {
        mesh.faceVertexCounts.push_back(std::int32_t(corners.size()));
        mesh.faceVertexIndices.insert(mesh.faceVertexIndices.end(), corners);
    }

    // Joins ring (or pole) a, lower on the profile, to b. With the ring parameterized by
    // phi counter-clockwise about +Y, (a_s, a_s+1, b_s+1, b_s) winds outward.
    void join(std::int32_t a, bool aPole, std::int32_t b, bool bPole) {
        for (int s = 0; s < segments; ++s) {
            const int t = (s + 1) % segments;
            if (aPole) addFace({a, b + t, b + s});
            else if (bPole) addFace({a + s, a + t, b});
            else addFace({a + s, a + t, b + t, b + s});
        }
    }
};

}  // namespace

ControlMesh makeSurfaceOfRevolution(std::span<const Imath::V2f> profile, int segments, std::string name) {
    if (profile.size() < 2 || segments < 3)
        throw Error("surface of revolution '" + name + "': needs 2+ profile points and 3+ segments");
    RevolutionBuilder b{ControlMesh{}, segments};
    b.mesh.source = std::move(name);
    std::int32_t previous = b.addRing(profile[0]);
    for (std::size_t i = 1; i < profile.size(); ++i) {
        const std::int32_t ring = b.addRing(profile[i]);
        b.join(previous, profile[i - 1].x == 0.0f, ring, profile[i].x == 0.0f);
        previous = ring;
    }
    return b.mesh;
}

namespace {

// A profile point of the candle, with how much of the rim's wobble it takes (0 none, 1 all).
struct CandleProfilePoint {
    Imath::V2f point;
    float wobbleWeight = 0.0f;
};

// The crest's height offset at angle phi, at most CandleSize::rimWobble either way and zero
// on average around the circle: two slow waves, as wax melts unevenly.
double rimWobble(double phi) {
    return CandleSize::rimWobble * (0.6 * std::sin(3.0 * phi + 0.7) + 0.4 * std::sin(5.0 * phi + 2.1));
}

// The vertex index of ring k's first vertex: the profile's poles take one vertex, rings
// `segments` (makeSurfaceOfRevolution's order).
std::size_t firstVertexOfRing(std::span<const CandleProfilePoint> profile, std::size_t ring, int segments) {
    std::size_t first = 0;
    for (std::size_t k = 0; k < ring; ++k) first += profile[k].point.x == 0.0f ? 1 : std::size_t(segments);
    return first;
}

// (radius, height) in mm from the base centre out and up the wall, over the rim and down
// into the pool to its centre. Rings are about as far apart as the sectors (2 pi 20 / 32 =
// 3.9 mm), so the faces stay near square: with faces 20 mm tall and 4 mm wide the body
// showed vertical streaks, in the exact reference's render too (the samples' charts
// follow the faces). The crest is three rings at
// rimHeight, so that the limit surface's profile (a cubic B-spline of these points) is
// flat there and keeps the height; the inner wall falls steeply, the pool floor rises
// gently to it.
std::vector<CandleProfilePoint> candleProfile() {
    using C = CandleSize;
    std::vector<CandleProfilePoint> profile = {
        {{0.0f, 0.0f}}, {{4.0f, 0.0f}}, {{8.0f, 0.0f}}, {{12.0f, 0.0f}}, {{15.5f, 0.0f}}, {{18.0f, 0.1f}},
        {{19.5f, 0.5f}}, {{C::radius, 2.0f}},
    };
    for (float y = 6.0f; y <= 74.0f; y += 4.0f) profile.push_back({{C::radius, y}});
    const CandleProfilePoint top[] = {
        {{C::radius, 77.0f}, 0.3f},     {{19.85f, 79.2f}, 0.7f},        {{19.4f, C::rimHeight}, 1.0f},
        {{18.8f, C::rimHeight}, 1.0f},  {{C::rimInner, C::rimHeight}, 1.0f}, {{17.8f, 79.2f}, 0.7f},
        {{17.4f, 77.6f}, 0.3f},         {{16.6f, 76.3f}},               {{13.0f, 75.6f}},
        {{9.5f, 75.3f}},                {{6.0f, 75.1f}},                {{3.0f, C::poolCentre}},
        {{0.0f, C::poolCentre}},
    };
    profile.insert(profile.end(), std::begin(top), std::end(top));
    return profile;
}

}  // namespace

ControlMesh makeCandle() {
    using C = CandleSize;
    const std::vector<CandleProfilePoint> profile = candleProfile();
    std::vector<Imath::V2f> points;
    for (const CandleProfilePoint& p : profile) points.push_back(p.point);
    ControlMesh mesh = makeSurfaceOfRevolution(points, C::segments, "builtin:candle");
    for (std::size_t ring = 0; ring < profile.size(); ++ring) {
        if (profile[ring].wobbleWeight == 0.0f) continue;
        const std::size_t first = firstVertexOfRing(profile, ring, C::segments);
        for (int s = 0; s < C::segments; ++s)
            mesh.positions[first + s].y +=
                float(profile[ring].wobbleWeight * rimWobble(2.0 * std::numbers::pi * s / C::segments));
    }
    return mesh;
}

ControlMesh makeWick() {
    using W = WickSize;
    const float base = CandleSize::poolCentre - W::depth, tip = CandleSize::poolCentre + W::height;
    // A cylinder with rounded ends: rings every 1.5 mm or so, so that the bend stays smooth.
    const Imath::V2f profile[] = {
        {0.0f, base},           {W::radius * 0.6f, base + 0.1f}, {W::radius, base + 0.5f},
        {W::radius, base + 2.5f}, {W::radius, base + 4.0f},       {W::radius, base + 5.5f},
        {W::radius, base + 7.0f}, {W::radius, base + 8.5f},       {W::radius, base + 10.0f},
        {W::radius, tip - 0.5f},  {W::radius * 0.6f, tip - 0.1f}, {0.0f, tip},
    };
    ControlMesh mesh = makeSurfaceOfRevolution(profile, W::segments, "builtin:wick");
    // Above the pool the axis bends toward +X, quadratically in the height (so it leaves
    // the wax vertically): the tip ends `lean` off the axis.
    for (Imath::V3f& p : mesh.positions) {
        const float s = std::max(0.0f, (p.y - CandleSize::poolCentre) / W::height);
        p.x += W::lean * s * s;
    }
    return mesh;
}

std::optional<ControlMesh> builtinMesh(std::string_view input) {
    if (input == "builtin:candle") return makeCandle();
    if (input == "builtin:wick") return makeWick();
    if (input.starts_with("builtin:"))
        throw Error("unknown built-in mesh '" + std::string(input) + "' (one of " + builtinMeshNames() + ")");
    return std::nullopt;
}

std::string builtinMeshNames() {
    return "builtin:candle, builtin:wick";
}

}  // namespace opal
