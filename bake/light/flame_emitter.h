// A candle flame: a teardrop surface of revolution about +Y with its base at the origin,
// round below, pointed at the tip, whose radius at height y = t H is
//   r(t) = (R / 0.3248) sqrt(t) (1 - t)^1.5,   t in [0, 1],
// widest (R) a quarter of the way up. Its emission is procedural: a ray meeting the
// surface at |cos| mu between its direction and the normal (1 at the middle of the flame
// as seen, 0 at its silhouette) at height fraction t sees radiance
//   L = luminance (0.25 + 0.75 mu) rgb(T),  T = T_rim + (T_core - T_rim) mu (1 - t^2),
// with rgb(T) the unit-luminance ACEScg (working space) colour of a black body at T
// (blackbody.h): a hotter, whiter, brighter core and an orange, dimmer rim and tip.
// Defaults: T_core 3000 K (yellow-white), T_rim 1700 K (orange), luminance 1: seen
// whole, about 2400 K, a little whiter than a real candle's 1850 K.
#pragma once

#include "bake/light/emitter.h"

namespace opal {

struct FlameShape {
    double height = 20.0;  // mm, base to tip
    double radius = 4.0;   // mm, widest
    double coreKelvin = 3000.0;
    double rimKelvin = 1700.0;
    double luminance = 1.0;
};

// Throws opal::Error for non-positive or non-finite sizes or luminance, or temperatures
// outside [500, 40000] K.
Emitter flameEmitter(const FlameShape& shape);

}  // namespace opal
