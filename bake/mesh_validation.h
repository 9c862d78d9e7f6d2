// Checking a control mesh before it is subdivided, and repairing what is safe to repair.
//
// Refused with an opal::Error naming the source, the first offender and how many there
// are: an empty mesh, a face with fewer than 3 corners, corner counts that do not add up,
// out-of-range vertex or UV indices, non-finite positions, non-manifold edges (used by more
// than two faces), inconsistent winding (two faces walking a shared edge in the same
// direction) unless RepairOptions::fixWinding, and non-orientable surfaces.
//
// Repaired, each with a warning that says how much: vertices with identical positions are
// welded (importers split them at UV seams); consecutive repeated corners are removed;
// faces left with a repeated vertex or fewer than 3 distinct vertices, and faces whose area
// is zero up to float rounding, are dropped; with fixWinding, faces are reoriented to agree
// with their neighbours; a closed mesh that encloses negative volume (inside out) has every
// face reversed; unreferenced vertices are dropped.
//
// Winding is refused by default because a pipeline cannot tell a flipped face from a
// modelling error; with fixWinding each connected component is made consistent by a
// breadth-first walk and keeps the orientation of the majority of its faces.
#pragma once

#include "bake/control_mesh.h"

#include <string>
#include <vector>

namespace opal {

struct RepairOptions {
    // Also weld vertices closer than this fraction of the bounding-box diagonal. 0 welds
    // only identical positions.
    double weldTolerance = 0.0;
    // Reorient faces whose winding disagrees with their neighbours instead of refusing.
    bool fixWinding = false;
};

struct ValidationReport {
    std::vector<std::string> warnings;  // one line per repair, with counts
};

// Validates `mesh` and repairs it in place; face and vertex numbers in messages are the
// input's. Throws opal::Error for what cannot be repaired.
ValidationReport validateAndRepair(ControlMesh& mesh, const RepairOptions& options = {});

}  // namespace opal
