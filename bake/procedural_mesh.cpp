#include "bake/procedural_mesh.h"

#include "schema/error.h"

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

ControlMesh makeCandle() {
    // (radius, height) in mm, bottom centre to the top centre at the wick.
    const Imath::V2f profile[] = {
        {0.0f, 0.0f},   {10.0f, 0.0f},  {18.0f, 0.0f},  {20.0f, 1.5f},  {20.0f, 20.0f},
        {20.0f, 40.0f}, {20.0f, 60.0f}, {20.0f, 76.0f}, {19.0f, 79.5f}, {16.0f, 79.8f},
        {11.0f, 78.6f}, {5.0f, 77.2f},  {0.0f, 77.0f},
    };
    return makeSurfaceOfRevolution(profile, 24, "builtin:candle");
}

}  // namespace opal
