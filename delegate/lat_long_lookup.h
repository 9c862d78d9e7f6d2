// Lat-long coordinates of directions at the rate the renderer needs them: once or twice per
// pixel (the visible dome behind the meshes, the specular layer's reflection; DESIGN.md s.7).
// LatLongMap::coordinates (environment_light.h) calls libm's asin and atan2, which cost
// most of a dome lookup; these give the same (u, v) to ~1e-15 with one rational
// approximation (Cephes' atan: x + x^3 P(x^2)/Q(x^2) for |x| <= 0.66, ~1e-16 relative,
// on the ratio min/max of |y| and |x|, shifted by pi/4 above 0.66) and
// asin(y / |d|) = atan2(y, sqrt(x^2 + z^2)).
//
// The float overloads are what the pixel loop uses: a degree-11 odd minimax polynomial
// for atan on [0, 1] (max error about 1e-5 rad; tests bound it by 2e-5), one division,
// no libm. 1e-5 rad is 1/600 of a pixel of a 1k lat-long map (6.1e-3 rad); measured, it
// takes the frame's dome lookups (background and specular reflection) from about a
// quarter of the frame's CPU time to about a tenth.
#pragma once

#include <Imath/ImathVec.h>

namespace opal {

// atan2(y, x) to a few ulps; signed zeros and the origin as std::atan2.
double fastAtan2(double y, double x);

// LatLongMap::coordinates(direction): (u, v) = (1/2 (1 - phi/pi), 1/2 - theta/pi) with
// phi = atan2(x, z), theta = asin(y / |d|). The direction need not be unit.
Imath::V2d latLongCoordinates(const Imath::V3d& direction);

// atan2(y, x) in float to about 1e-5 rad; the origin gives 0.
float fastAtan2(float y, float x);
// latLongCoordinates in float, to about 1e-5 / pi in u and v.
Imath::V2f latLongCoordinates(const Imath::V3f& direction);

}  // namespace opal
