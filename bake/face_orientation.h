// Which way faces wind. Two faces sharing a manifold edge agree when they walk it in
// opposite directions; a closed mesh whose faces agree encloses a positive volume when they
// wind counter-clockwise seen from outside.
#pragma once

#include "bake/mesh_edges.h"

#include <Imath/ImathVec.h>

#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace opal {

struct FaceOrientation {
    std::vector<char> reversed;  // per face: 1 if it must be reversed to agree
    // Set when no choice agrees (a non-orientable surface, e.g. a Moebius strip): a face the
    // walk reached with both orientations, and the face it came from.
    std::optional<std::pair<std::int32_t, std::int32_t>> conflict;
};

// Walks each connected component (across edges with exactly two faces) breadth first from
// its lowest face, then keeps the orientation most of the component's faces already have,
// so as few faces as possible are reversed.
FaceOrientation orientFacesConsistently(const MeshEdges& edges, std::span<const std::int32_t> faceVertexCounts);

// The signed volume the faces enclose (fan triangles against the bounding-box centre):
// positive when a closed mesh winds counter-clockwise seen from outside.
double enclosedVolume(std::span<const Imath::V3f> positions, std::span<const std::int32_t> faceVertexCounts,
                      std::span<const std::int32_t> faceVertexIndices);

}  // namespace opal
