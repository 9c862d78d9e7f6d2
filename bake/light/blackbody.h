// The colour of a black body at a temperature, as linear Rec.709 RGB of unit luminance:
//   1. Planck's spectral radiance B(lambda, T) = 2 h c^2 / lambda^5 / (exp(h c / (lambda k T)) - 1)
//      at 380..780 nm every 1 nm;
//   2. integrated against the CIE 1931 2-degree colour matching functions (the
//      multi-lobe Gaussian fit of Wyman, Sloan and Shirley 2013, within a few per cent
//      of the tables) to XYZ;
//   3. XYZ to linear Rec.709 (sRGB primaries, D65 white) with the standard matrix
//      (IEC 61966-2-1);
//   4. negative components clamped to 0 (below about 1600 K the Planckian locus leaves
//      Rec.709's gamut past the red-green edge), then scaled to luminance
//      Y = 0.2126 R + 0.7152 G + 0.0722 B = 1.
#pragma once

#include <Imath/ImathVec.h>

namespace opal {

// Throws opal::Error unless kelvin is in [500, 40000].
Imath::V3d blackbodyRec709(double kelvin);
// The CIE 1931 chromaticity (x, y) of a black body (steps 1 and 2), for checking.
Imath::V2d blackbodyChromaticity(double kelvin);

}  // namespace opal
