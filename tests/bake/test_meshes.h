// Small meshes made in code for the bake tests, with the closed-form facts the tests
// compare against. Faces wind counter-clockwise seen from outside.
#pragma once

#include "bake/control_mesh.h"
#include "schema/asset/fan_triangulation.h"
#include "schema/asset/translucent_asset.h"

#include <Imath/ImathVec.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace opal::test {

// The mesh as Wavefront OBJ text (positions and faces only), for bakes through a file.
inline std::string objText(const ControlMesh& mesh) {
    std::ostringstream obj;
    obj.precision(9);
    for (const Imath::V3f& p : mesh.positions) obj << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    std::size_t at = 0;
    for (std::int32_t n : mesh.faceVertexCounts) {
        obj << 'f';
        for (std::int32_t c = 0; c < n; ++c) obj << ' ' << mesh.faceVertexIndices[at++] + 1;
        obj << '\n';
    }
    return obj.str();
}

inline void addFace(ControlMesh& mesh, std::initializer_list<std::int32_t> corners) {
    mesh.faceVertexCounts.push_back(std::int32_t(corners.size()));
    mesh.faceVertexIndices.insert(mesh.faceVertexIndices.end(), corners);
}

// The axis-aligned cube [-half, half]^3 as 6 quads.
inline ControlMesh cube(float half = 0.5f) {
    ControlMesh mesh;
    mesh.source = "cube";
    for (int i = 0; i < 8; ++i) {
        mesh.positions.emplace_back(i & 1 ? half : -half, i & 2 ? half : -half, i & 4 ? half : -half);
    }
    addFace(mesh, {0, 2, 3, 1});  // -z
    addFace(mesh, {4, 5, 7, 6});  // +z
    addFace(mesh, {0, 1, 5, 4});  // -y
    addFace(mesh, {2, 6, 7, 3});  // +y
    addFace(mesh, {0, 4, 6, 2});  // -x
    addFace(mesh, {1, 3, 7, 5});  // +x
    return mesh;
}

// The regular octahedron with vertices at distance `radius` on the axes: 8 triangles.
inline ControlMesh octahedron(float radius = 1.0f) {
    ControlMesh mesh;
    mesh.source = "octahedron";
    mesh.positions = {{radius, 0, 0}, {-radius, 0, 0}, {0, radius, 0}, {0, -radius, 0}, {0, 0, radius}, {0, 0, -radius}};
    addFace(mesh, {0, 2, 4});
    addFace(mesh, {2, 1, 4});
    addFace(mesh, {1, 3, 4});
    addFace(mesh, {3, 0, 4});
    addFace(mesh, {2, 0, 5});
    addFace(mesh, {1, 2, 5});
    addFace(mesh, {3, 1, 5});
    addFace(mesh, {0, 3, 5});
    return mesh;
}

// The regular icosahedron inscribed in the sphere of `radius`: 12 vertices, 20 triangles.
inline ControlMesh icosahedron(float radius = 1.0f) {
    ControlMesh mesh;
    mesh.source = "icosahedron";
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    const float s = radius / std::sqrt(1.0f + t * t);
    mesh.positions = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                      {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (Imath::V3f& p : mesh.positions) p *= s;
    for (auto f : std::vector<std::vector<std::int32_t>>{
             {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
             {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}}) {
        mesh.faceVertexCounts.push_back(3);
        mesh.faceVertexIndices.insert(mesh.faceVertexIndices.end(), f.begin(), f.end());
    }
    return mesh;
}

// An icosahedron with each triangle split into 4, `levels` times, projected onto the sphere.
inline ControlMesh icosphere(int levels, float radius = 1.0f) {
    ControlMesh mesh = icosahedron(radius);
    mesh.source = "icosphere";
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<std::int32_t, std::int32_t>, std::int32_t> midpoints;
        auto midpoint = [&](std::int32_t a, std::int32_t b) {
            std::pair<std::int32_t, std::int32_t> key(std::min(a, b), std::max(a, b));
            auto [it, inserted] = midpoints.try_emplace(key, std::int32_t(mesh.positions.size()));
            if (inserted) mesh.positions.push_back((mesh.positions[a] + mesh.positions[b]).normalized() * radius);
            return it->second;
        };
        std::vector<std::int32_t> old = mesh.faceVertexIndices;
        mesh.faceVertexCounts.clear();
        mesh.faceVertexIndices.clear();
        for (std::size_t f = 0; f < old.size(); f += 3) {
            std::int32_t a = old[f], b = old[f + 1], c = old[f + 2];
            std::int32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            addFace(mesh, {a, ab, ca});
            addFace(mesh, {b, bc, ab});
            addFace(mesh, {c, ca, bc});
            addFace(mesh, {ab, bc, ca});
        }
    }
    return mesh;
}

// A torus around the z axis: major radius R, minor radius r, nu x nv quads.
inline ControlMesh torus(float majorRadius, float minorRadius, int nu, int nv) {
    ControlMesh mesh;
    mesh.source = "torus";
    for (int i = 0; i < nu; ++i) {
        for (int j = 0; j < nv; ++j) {
            double u = 2 * std::numbers::pi * i / nu, v = 2 * std::numbers::pi * j / nv;
            double ring = majorRadius + minorRadius * std::cos(v);
            mesh.positions.emplace_back(float(ring * std::cos(u)), float(ring * std::sin(u)),
                                        float(minorRadius * std::sin(v)));
        }
    }
    auto at = [&](int i, int j) { return std::int32_t(((i + nu) % nu) * nv + (j + nv) % nv); };
    for (int i = 0; i < nu; ++i) {
        for (int j = 0; j < nv; ++j) addFace(mesh, {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
    return mesh;
}

// The open square [0, size]^2 in the plane z = 0, n x n quads, facing +z.
inline ControlMesh planeGrid(int n, float size = 1.0f) {
    ControlMesh mesh;
    mesh.source = "plane";
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) mesh.positions.emplace_back(size * i / n, size * j / n, 0.0f);
    }
    auto at = [&](int i, int j) { return std::int32_t(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) addFace(mesh, {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
    return mesh;
}

// A control mesh used directly as a render mesh, with the given per-vertex normals.
template <class NormalAt>
RenderMesh asRenderMesh(const ControlMesh& mesh, NormalAt normalAt) {
    RenderMesh out;
    out.points = mesh.positions;
    for (const Imath::V3f& p : mesh.positions) out.normals.push_back(normalAt(p).normalized());
    out.faceVertexCounts = mesh.faceVertexCounts;
    out.faceVertexIndices = mesh.faceVertexIndices;
    return out;
}

inline RenderMesh sphereRenderMesh(int levels, float radius = 1.0f) {
    return asRenderMesh(icosphere(levels, radius), [](const Imath::V3f& p) { return p; });
}

// The exact torus normal: away from the nearest point of the core circle.
inline Imath::V3f torusNormal(const Imath::V3f& p, float majorRadius) {
    Imath::V3f core(p.x, p.y, 0.0f);
    core = core.normalized() * majorRadius;
    return (p - core).normalized();
}

inline RenderMesh torusRenderMesh(float majorRadius, float minorRadius, int nu, int nv) {
    return asRenderMesh(torus(majorRadius, minorRadius, nu, nv),
                        [&](const Imath::V3f& p) { return torusNormal(p, majorRadius); });
}

// The polyhedral area of a mesh: sum of its fan triangles, in double.
inline double polygonArea(const std::vector<Imath::V3f>& points, const std::vector<std::int32_t>& counts,
                          const std::vector<std::int32_t>& indices) {
    double area = 0.0;
    forEachFanTriangle(counts, indices, [&](std::size_t, const std::array<std::int32_t, 3>& v) {
        const Imath::V3d p0(points[std::size_t(v[0])]), a(points[std::size_t(v[1])]), b(points[std::size_t(v[2])]);
        area += 0.5 * (a - p0).cross(b - p0).length();
    });
    return area;
}

inline double renderMeshArea(const RenderMesh& mesh) {
    return polygonArea(mesh.points, mesh.faceVertexCounts, mesh.faceVertexIndices);
}

}  // namespace opal::test
