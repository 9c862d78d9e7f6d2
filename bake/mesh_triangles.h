// The render mesh's polygons as triangles, with each triangle's face and area: what the
// surface sampler draws from. Polygons are split into fans (schema/asset/fan_triangulation.h).
#pragma once

#include "schema/asset/translucent_asset.h"

#include <array>
#include <cstdint>
#include <vector>

namespace opal {

struct MeshTriangle {
    std::array<std::uint32_t, 3> vertices;  // render-mesh vertex indices, counter-clockwise
    std::uint32_t face;                     // the render-mesh face it is part of
};

struct MeshTriangles {
    std::vector<MeshTriangle> triangles;
    std::vector<double> areas;  // per triangle
    double totalArea = 0.0;     // summed in triangle order
};

MeshTriangles triangulate(const RenderMesh& mesh);

}  // namespace opal
