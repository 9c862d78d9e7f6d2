// The colour of a black body at a temperature, in the working space ACEScg, of unit luminance:
//   1. Planck's spectral radiance B(lambda, T) = 2 h c^2 / lambda^5 / (exp(h c / (lambda k T)) - 1)
//      at 380..780 nm every 1 nm;
//   2. integrated against the CIE 1931 2-degree colour matching functions (the
//      multi-lobe Gaussian fit of Wyman, Sloan and Shirley 2013, within a few per cent
//      of the tables) to XYZ;
//   3. XYZ (taken as D65-referred) to ACEScg with kXyzD65ToAcescg (acescg_from_xyz.h:
//      AP1 primaries after a Bradford adaptation D65 -> ACES white);
//   4. scaled to luminance 1 by AP1's Y row (kAcescgLuminance).
// No component is ever negative: AP1 holds the Planckian locus over the whole range,
// down to 500 K (Rec.709 loses it below about 1600 K).
#pragma once

#include <Imath/ImathVec.h>

namespace opal {

// Throws opal::Error unless kelvin is in [500, 40000].
Imath::V3d blackbodyAcescg(double kelvin);
// The CIE 1931 chromaticity (x, y) of a black body (steps 1 and 2), for checking.
Imath::V2d blackbodyChromaticity(double kelvin);

}  // namespace opal
