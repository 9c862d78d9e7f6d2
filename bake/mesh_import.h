// Reading control meshes from files. Polygons are kept as authored (no triangulation):
// Catmull-Clark needs the quads. Vertices are returned as the reader produced them, which
// for Assimp means split at UV and normal seams; mesh validation welds them back. USDA
// layers go through Opal's own reader (bake/usda_mesh_import.h).
#pragma once

#include "bake/control_mesh.h"
#include "bake/subdivision.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace opal {

struct ImportedMesh {
    ControlMesh mesh;
    std::vector<std::string> warnings;  // what the import skipped, with counts
    // The scheme the file asks for (USDA subdivisionScheme); nullopt when it says nothing.
    // The bake honours it when --scheme is auto.
    std::optional<SubdivisionScheme> authoredScheme;
    // The file's scale (USDA layer metersPerUnit), for the bake to report against
    // --units-per-mm; never applied to the positions.
    std::optional<double> metersPerUnit;
};

// Reads .obj, .ply, .gltf, .glb, .stl and .usda (by extension, case-insensitive). Every
// mesh in the file is merged into one, with its node (prim) transforms applied. PLY
// triangle strips are decoded into triangles (bake/ply_triangle_strips.h). Throws
// opal::Error naming the path for a missing or unreadable file, an unsupported extension,
// a reader failure, or a result that is implausible for the file (fewer faces than the
// file holds, none, triangle strips that hold no triangle, zero total area).
ImportedMesh importMesh(const std::filesystem::path& path);

// One Mesh prim of a .usda layer, in its own space (importUsdaMeshPrim); the same checks
// as importMesh. Any other format is refused, naming the path.
ImportedMesh importMeshPrim(const std::filesystem::path& path, const std::string& primPath);

// The extensions importMesh accepts, for help texts: ".obj .ply .gltf .glb .stl .usda".
std::string supportedMeshExtensions();

}  // namespace opal
