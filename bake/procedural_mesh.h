// Control meshes made in code: the built-in candle of the main job (`opal-bake
// builtin:candle`), and surfaces of revolution in general. Units: millimetres; +Y up.
#pragma once

#include "bake/control_mesh.h"

#include <Imath/ImathVec.h>

#include <span>
#include <string>
#include <vector>

namespace opal {

// Revolves a profile of (radius, height) points about +Y with `segments` sectors. A point
// with radius 0 is a pole (a triangle fan); the others become rings, joined by quads.
// The profile runs from the bottom to the top, so faces wind counter-clockwise seen from
// outside.
ControlMesh makeSurfaceOfRevolution(std::span<const Imath::V2f> profile, int segments, std::string name);

// A pillar candle 40 mm across and about 80 mm tall, with a softened rim and a shallow
// melt pool around the wick.
ControlMesh makeCandle();

}  // namespace opal
