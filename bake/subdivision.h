// Subdividing the control mesh into the render mesh with OpenSubdiv (Far): uniform
// refinement to a level, then every refined vertex is moved to the limit surface and
// given the limit normal, so the render mesh's vertices lie exactly on the smooth surface
// the artist modelled.
#pragma once

#include "bake/control_mesh.h"
#include "schema/asset/translucent_asset.h"

#include <string_view>

namespace opal {

enum class SubdivisionScheme {
    Automatic,     // Loop when every face is a triangle, else Catmull-Clark
    CatmullClark,  // quads (any polygon in; quads out)
    Loop,          // triangles only
    Bilinear,      // flat: faces are split, never smoothed. Only from a file's own scheme
                   // (USD "bilinear" or "none"), not a --scheme choice.
};

struct SubdivisionOptions {
    SubdivisionScheme scheme = SubdivisionScheme::Automatic;
    int level = 2;  // uniform refinement levels; each multiplies the face count by 4
};

// "auto", "catmullClark" or "loop" (the names BakeSettings::scheme and USD use). Throws
// opal::Error listing the valid names otherwise.
SubdivisionScheme parseSubdivisionScheme(std::string_view name);
std::string_view subdivisionSchemeName(SubdivisionScheme scheme);

// What Automatic means for this mesh; a forced Loop on a mesh with non-triangular faces is
// refused with an opal::Error naming the first such face.
SubdivisionScheme resolveSubdivisionScheme(const ControlMesh& mesh, SubdivisionScheme requested);

// Refines a validated control mesh (see validateAndRepair). Boundaries interpolate edges
// and corners. Normals are unit, normalize(dP/du x dP/dv), which points to the side the
// faces wind counter-clockwise around: outward for a validated closed mesh. Bilinear
// keeps the refined points on the control polygons and gives each vertex the normalized
// area-weighted normal of its faces (a flat surface has no limit normal at its edges). Throws
// opal::Error for a bad level or when OpenSubdiv rejects the topology.
RenderMesh subdivide(const ControlMesh& mesh, const SubdivisionOptions& options);

}  // namespace opal
