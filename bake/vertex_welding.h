// Welding vertices that share a position. Importers split vertices at UV and normal seams
// and STL stores every triangle separately; subdivision needs one vertex per point of the
// surface, or it sees cracks (boundaries) where the surface is closed.
#pragma once

#include <Imath/ImathVec.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace opal {

struct VertexWelding {
    // For each vertex, the vertex it merges into: the lowest index of its group, so a
    // vertex that stays is its own representative.
    std::vector<std::int32_t> representative;
    std::size_t welded = 0;  // vertices that merged into another one
};

// Vertices with exactly equal coordinates (+0 and -0 are equal). O(n log n).
VertexWelding weldIdenticalPositions(std::span<const Imath::V3f> positions);

// Each vertex, in index order, merges into the lowest-index representative within
// `tolerance` (Euclidean), or becomes a representative. Merging is not transitive: a chain
// of points each within tolerance of the next does not collapse into one vertex.
VertexWelding weldNearbyPositions(std::span<const Imath::V3f> positions, float tolerance);

}  // namespace opal
