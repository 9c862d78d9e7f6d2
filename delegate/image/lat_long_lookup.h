// Lat-long coordinates of directions at the rate the renderer needs them: once or twice per pixel
// (the visible dome behind the meshes, the specular layer's reflection;
// docs/ARCHITECTURE.md#image-formation; dome_lookup.h). LatLongMap::coordinates
// (environment_light.h) calls libm's asin and atan2, which cost most of a dome lookup. Here atan2
// is a degree-11 odd minimax polynomial for atan on [0, 1] (max error about 1e-5 rad; tests bound
// it by 2e-5) on the ratio min/max of |y| and |x|, one division, no libm, and
// asin(y / |d|) = atan2(y, sqrt(x^2 + z^2)). 1e-5 rad is 1/600 of a pixel of a 1k lat-long map
// (6.1e-3 rad).
#pragma once

#include <Imath/ImathVec.h>

namespace opal {

// atan2(y, x) in float to about 1e-5 rad; the origin gives 0.
float fastAtan2(float y, float x);
// LatLongMap::coordinates(direction), to about 1e-5 / pi in u and v: (u, v) =
// (1/2 (1 - phi/pi), 1/2 - theta/pi) with phi = atan2(x, z), theta = asin(y / |d|). The
// direction need not be unit.
Imath::V2f latLongCoordinates(const Imath::V3f& direction);

}  // namespace opal
