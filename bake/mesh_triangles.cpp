#include "bake/mesh_triangles.h"

#include "schema/asset/fan_triangulation.h"

#include <tbb/parallel_for.h>

namespace opal {

MeshTriangles triangulate(const RenderMesh& mesh) {
    MeshTriangles result;
    forEachFanTriangle(mesh.faceVertexCounts, mesh.faceVertexIndices,
                       [&](std::size_t face, const std::array<std::int32_t, 3>& v) {
                           result.triangles.push_back(
                               {{std::uint32_t(v[0]), std::uint32_t(v[1]), std::uint32_t(v[2])}, std::uint32_t(face)});
                       });
    result.areas.resize(result.triangles.size());
    tbb::parallel_for(std::size_t(0), result.triangles.size(), [&](std::size_t t) {
        const auto& v = result.triangles[t].vertices;
        Imath::V3d a(mesh.points[v[0]]), b(mesh.points[v[1]]), c(mesh.points[v[2]]);
        result.areas[t] = 0.5 * (b - a).cross(c - a).length();
    });
    for (double area : result.areas) result.totalArea += area;  // in order: deterministic
    return result;
}

}  // namespace opal
