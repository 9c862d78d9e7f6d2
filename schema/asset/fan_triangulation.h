// Opal's one triangulation of polygons: each face (c0, c1, ..., c(n-1)) becomes the fan
// (c0, c(t+1), c(t+2)) for t = 0 .. n-3, which keeps the face's winding. Render-mesh
// faces (refined quads and triangles) and control-mesh faces are close to planar and
// convex, where a fan is exact. The bake samples and measures these triangles, the ray
// scene intersects them, and a triangle's index within its mesh is its place in this order.
#pragma once

#include "schema/error.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace opal {

// Calls visit(face, {v0, v1, v2}) with the vertex indices of every fan triangle, face by
// face in order; faces of fewer than 3 corners give none. Throws opal::Error naming the
// face when the counts run past the indices.
template <class Visit>
void forEachFanTriangle(std::span<const std::int32_t> faceVertexCounts, std::span<const std::int32_t> faceVertexIndices,
                        Visit&& visit) {
    std::size_t corner = 0;
    for (std::size_t face = 0; face < faceVertexCounts.size(); ++face) {
        const std::int32_t count = faceVertexCounts[face];
        if (count > 0 && std::size_t(count) > faceVertexIndices.size() - corner)
            throw Error("face " + std::to_string(face) + " has " + std::to_string(count) + " corners, past the " +
                        std::to_string(faceVertexIndices.size()) + " face-vertex indices");
        for (std::int32_t t = 0; t + 2 < count; ++t) {
            const std::array<std::int32_t, 3> triangle = {faceVertexIndices[corner],
                                                          faceVertexIndices[corner + std::size_t(t) + 1],
                                                          faceVertexIndices[corner + std::size_t(t) + 2]};
            visit(face, triangle);
        }
        if (count > 0) corner += std::size_t(count);
    }
}

}  // namespace opal
