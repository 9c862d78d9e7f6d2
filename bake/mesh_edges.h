// The undirected edges of a polygon mesh and the face corners that use them: what
// manifoldness, winding consistency and reorientation are decided on.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace opal {

class MeshEdges {
public:
    // Corner `corner` (an index into faceVertexIndices) of `face` starts the edge to the
    // face's next corner. `forward`: the face walks it from the lower vertex index to the
    // higher one.
    struct Use {
        std::int32_t face;
        std::int32_t corner;
        bool forward;
    };
    struct Edge {
        std::int32_t low, high;  // vertex indices, low < high
        std::uint32_t firstUse, useCount;
    };

    // Faces must have at least 2 distinct corners; edges are sorted by (low, high) and
    // the uses of an edge by face, so everything built on them is deterministic.
    MeshEdges(std::span<const std::int32_t> faceVertexCounts, std::span<const std::int32_t> faceVertexIndices);

    const std::vector<Edge>& edges() const { return edges_; }
    std::span<const Use> uses(const Edge& edge) const { return {uses_.data() + edge.firstUse, edge.useCount}; }
    // The edge that starts at a corner (an index into faceVertexIndices).
    std::int32_t edgeOfCorner(std::size_t corner) const { return cornerEdge_[corner]; }

private:
    std::vector<Edge> edges_;
    std::vector<Use> uses_;
    std::vector<std::int32_t> cornerEdge_;
};

}  // namespace opal
