#include "bake/mesh_triangles.h"

#include <tbb/parallel_for.h>

namespace opal {

MeshTriangles triangulate(const RenderMesh& mesh) {
    MeshTriangles result;
    std::size_t start = 0;
    for (std::size_t f = 0; f < mesh.faceVertexCounts.size(); ++f) {
        std::int32_t n = mesh.faceVertexCounts[f];
        for (std::int32_t c = 1; c + 1 < n; ++c) {
            result.triangles.push_back({{std::uint32_t(mesh.faceVertexIndices[start]),
                                         std::uint32_t(mesh.faceVertexIndices[start + c]),
                                         std::uint32_t(mesh.faceVertexIndices[start + c + 1])},
                                        std::uint32_t(f)});
        }
        start += std::size_t(n);
    }
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
