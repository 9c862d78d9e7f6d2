// Per-channel quantities (scattering coefficients, albedo, radiance) are RGB triples in the
// working color space (ACEScg unless the OCIO config says otherwise).
#pragma once

#include <Imath/ImathColor.h>
#include <Imath/ImathVec.h>

namespace opal {

using Rgb = Imath::Color3<double>;

// Luminance of an ACEScg colour: the Y row of AP1's RGB -> XYZ (SMPTE ST 2065-1 /
// Academy S-2014-004), for the shipped config's working space.
inline constexpr Imath::V3d kAcescgLuminance{0.2722287168, 0.6740817658, 0.0536895174};

}  // namespace opal
