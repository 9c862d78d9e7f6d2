// The control mesh a bake starts from: polygons as authored (quads stay quads), before
// subdivision. Positions are indexed per face corner; texture coordinates, when present,
// are face-varying (their own index per corner), because importers split vertices at UV
// seams and the subdivision topology must not see those splits.
#pragma once

#include <Imath/ImathVec.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace opal {

struct ControlMesh {
    std::string source;  // where the mesh came from (a path), for messages

    std::vector<Imath::V3f> positions;
    std::vector<std::int32_t> faceVertexCounts;   // corners per face
    std::vector<std::int32_t> faceVertexIndices;  // into positions, one per corner

    // Optional face-varying texture coordinates: uvIndices has one entry per corner
    // (parallel to faceVertexIndices) into uvs. Both empty when the mesh has none.
    std::vector<Imath::V2f> uvs;
    std::vector<std::int32_t> uvIndices;

    std::size_t faceCount() const { return faceVertexCounts.size(); }
    bool hasUvs() const { return !uvIndices.empty(); }
};

}  // namespace opal
