// Reading control meshes from USDA layers within Opal's USDA subset (schema/usd/SUBSET.md),
// into the same ImportedMesh the Assimp formats give, so validation and repair apply
// unchanged. Like the Assimp path for multi-mesh files, every Mesh prim USD would render
// is merged into one mesh with its transform applied:
//
// - prims are traversed as USD's default predicate does: `def` prims only (`class` is
//   abstract, `over` defines nothing in a lone layer), skipping inactive prims and, with a
//   warning, invisible ones and guide/proxy purposes (inherited from ancestors);
// - a Mesh prim gives points (point3f[]), faceVertexCounts and faceVertexIndices (int[]),
//   holeIndices (those faces are left out), orientation ("leftHanded" reverses every
//   face) and subdivisionScheme (exposed as ImportedMesh::authoredScheme when every Mesh
//   prim authors the same one; "bilinear" and "none" mean Bilinear: keep the polygons flat);
// - transforms: xformOps on the Mesh prim and its ancestors (prim_transform.h); a
//   mirroring transform reverses the faces, as in the Assimp path;
// - the layer's metersPerUnit is returned for the caller to report, never applied.
//
// Refused with an opal::Error "file:line:column: </Prim>.attribute: problem": syntax and
// anything outside the subset (the reader's own errors), a missing or mistyped points /
// faceVertexCounts / faceVertexIndices, a face with fewer than 3 corners, counts that do
// not add up, an out-of-range index, points that are not finite after the transform, an
// unknown orientation or subdivisionScheme, unsupported xformOps. Also refused, naming
// the file: composition Opal does not do (subLayers, references), and a layer without a
// Mesh prim. Authored creases and corners are ignored with a warning; normals, primvars
// (UVs included) and other non-geometric attributes are ignored silently.
#pragma once

#include "bake/mesh_import.h"

#include <filesystem>
#include <string>

namespace opal {

ImportedMesh importUsdaMesh(const std::filesystem::path& path);

// The one Mesh prim at `primPath` (opal-bake --apply-to), in its own space: neither its
// xformOps nor its ancestors' are applied, since the over-layer the bake writes for it
// keeps the prim's transform stack. Refused, besides the above: a path the layer does not
// hold, a prim on it that is a class, an over, inactive or has references, and a last
// prim that is not a Mesh (bake/usda_prim_lookup.h).
ImportedMesh importUsdaMeshPrim(const std::filesystem::path& path, const std::string& primPath);

}  // namespace opal
