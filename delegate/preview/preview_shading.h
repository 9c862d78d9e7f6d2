// How the preview shades a visible point: Lambert under a headlight, or the normal as a
// colour. The headlight is a distant light along the view ray (from the camera), so the
// radiance leaving a point with diffuse albedo rho toward the camera is
//
//     L = rho * intensity * max(0, n . v)
//
// (irradiance pi * intensity * cos theta times rho / pi), v the unit direction to the
// camera and n the unit shading normal: a sphere's centre, seen head on, shows rho * intensity.
#pragma once

#include "schema/scatter/rgb.h"

#include <Imath/ImathVec.h>

#include <algorithm>

namespace opal::preview {

enum class Shading { Lambert, Normals };

inline Rgb headlightLambert(const Rgb& albedo, double intensity, const Imath::V3f& normal, const Imath::V3f& toCamera) {
    const double cosine = std::max(0.0, double(normal.dot(toCamera)));
    return {albedo[0] * intensity * cosine, albedo[1] * intensity * cosine, albedo[2] * intensity * cosine};
}

// World-space unit normal n as 0.5 (n + 1): +X red, +Y green, +Z blue.
inline Rgb normalColor(const Imath::V3f& normal) {
    return {0.5 * (normal.x + 1.0), 0.5 * (normal.y + 1.0), 0.5 * (normal.z + 1.0)};
}

}  // namespace opal::preview
