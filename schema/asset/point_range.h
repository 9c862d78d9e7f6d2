// The range of positions an asset may hold: every coordinate finite and within
// kMaxDistanceMm (1,000 km) of the origin, measured in millimetres through the asset's
// unitsPerMm (metersPerUnit = 0.001 / unitsPerMm). Far beyond any object Opal bakes, and
// far inside what rays, offsets along normals and float sums can handle (raytrace/ray.h).
// The bake checks its input mesh, the reader every point and sample it loads.
#pragma once

#include <Imath/ImathVec.h>

#include <span>
#include <string_view>

namespace opal {

inline constexpr double kMaxDistanceMm = 1e9;

// Throws opal::Error "<context>: <what> <i> (x, y, z) is not finite" or "... lies <d> mm from
// the origin, beyond the 1e9 mm (1,000 km) an asset may span" for the first offending point.
void checkPointRange(std::span<const Imath::V3f> points, double unitsPerMm, std::string_view context,
                     std::string_view what);

}  // namespace opal
