// PLY meshes stored as triangle strips: an element "tristrips" with a list property
// "vertex_indices", in which -1 restarts the strip, as the classic Stanford and Cyberware
// scans (the Igea head among them) are stored. Assimp does not decode them (it returns a
// single face), so Opal reads such files itself.
//
// A strip v0 v1 v2 v3 ... stands for the triangles (v0 v1 v2), (v2 v1 v3), (v2 v3 v4), ...:
// triangle k is (v_k, v_k+1, v_k+2) for even k and (v_k+1, v_k, v_k+2) for odd k, so that
// every triangle of a strip has the first one's orientation. Triangles with a repeated
// vertex (the strips' way of turning or of joining runs) are dropped but still count for
// the alternation.
#pragma once

#include "bake/control_mesh.h"
#include "bake/ply_header.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

namespace opal {

struct StripTriangles {
    std::vector<std::int32_t> corners;  // three vertex indices per triangle
    std::uint64_t degenerate = 0;       // triangles dropped for a repeated vertex
};

// Appends the triangles of one strip list (with -1 restarts) to `out`. Indices other
// than -1 must be valid vertex indices (readPlyTriangleStrips checks them).
void decodeTriangleStrip(std::span<const std::int32_t> indices, StripTriangles& out);

bool declaresTriangleStrips(const PlyHeader& header);

struct PlyStripMesh {
    ControlMesh mesh;                 // triangles from the strips, then any 'face' polygons
    std::uint64_t stripTriangles = 0; // how many of the faces came from strips
    std::uint64_t degenerate = 0;
};

// Reads a PLY file (ASCII, binary little or big endian) whose header declares triangle
// strips: vertex x, y, z, the strips, and polygons of a 'face' element if it has one;
// other elements and properties are skipped. Throws opal::Error naming the file, the
// element and its index for a missing property, a malformed or missing value, an index
// that is neither -1 nor a vertex, or a declared count the file is too short to hold.
PlyStripMesh readPlyTriangleStrips(const std::filesystem::path& path, std::string_view bytes,
                                   const PlyHeader& header);

}  // namespace opal
