// Subdividing the control mesh into the render mesh with OpenSubdiv (Far): uniform
// refinement to a level, then every refined vertex is moved to the limit surface and
// given the limit normal, so the render mesh's vertices lie exactly on the smooth surface
// the artist modelled.
#pragma once

#include "bake/control_mesh.h"
#include "schema/asset/translucent_asset.h"

#include <cstdint>
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

// The level `--level auto` picks: the smallest in [0, kMaxAutomaticLevel] whose render
// mesh has at least as many vertices as the bake has samples (the finest level if none
// does). Subsurface radiance reaches the render mesh through per-vertex interpolation of
// the samples, so vertices beyond the sample count add geometry but no shading detail: a
// dense scan renders at level 0, a coarse cage is refined until it is as fine as the
// samples. Counted from the topology (uniform refinement: Catmull-Clark and bilinear split
// every n-gon into n quads, Loop every triangle into 4), without refining.
inline constexpr std::uint32_t kMaxAutomaticLevel = 6;
std::uint32_t automaticSubdivisionLevel(const ControlMesh& mesh, SubdivisionScheme scheme, std::uint64_t samples);

// Refines a validated control mesh (see validateAndRepair). Boundaries interpolate edges
// and corners. Normals are unit, normalize(dP/du x dP/dv), which points to the side the
// faces wind counter-clockwise around: outward for a validated closed mesh. Bilinear
// keeps the refined points on the control polygons and gives each vertex the normalized
// area-weighted normal of its faces (a flat surface has no limit normal at its edges). Throws
// opal::Error for a bad level or when OpenSubdiv rejects the topology.
RenderMesh subdivide(const ControlMesh& mesh, const SubdivisionOptions& options);

}  // namespace opal
