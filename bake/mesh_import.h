// Reading control meshes from files. Polygons are kept as authored (no triangulation):
// Catmull-Clark needs the quads. Vertices are returned as the reader produced them, which
// for Assimp means split at UV and normal seams; mesh validation welds them back.
#pragma once

#include "bake/control_mesh.h"

#include <filesystem>
#include <string>
#include <vector>

namespace opal {

struct ImportedMesh {
    ControlMesh mesh;
    std::vector<std::string> warnings;  // what the import skipped, with counts
};

// Reads .obj, .ply, .gltf, .glb and .stl (by extension, case-insensitive). Every mesh in
// the file is merged into one, with its node transforms applied. Throws opal::Error naming
// the path for a missing or unreadable file, an unsupported extension, a reader failure,
// or a result that is implausible for the file (fewer faces than the file holds, none).
ImportedMesh importMesh(const std::filesystem::path& path);

// The extensions importMesh accepts, for help texts: ".obj .ply .gltf .glb .stl".
std::string supportedMeshExtensions();

}  // namespace opal
