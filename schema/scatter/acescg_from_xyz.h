// CIE XYZ to Opal's working space, ACEScg (AP1 primaries, ACES white x = 0.32168,
// y = 0.33767, about D60), for colours computed from spectra (a flame, a colour temperature).
//
// XYZ from the CIE 1931 matching functions is taken as referred to a D65 adopted white, as
// the colour management does everywhere else (OCIO's "CIE-XYZ-D65" connection space; a
// Linear Rec.709 map is converted to ACEScg the same way): a D65 source maps to neutral
// (1, 1, 1), and AP1's own white is reached by a Bradford chromatic adaptation
// D65 -> ACES white. So XYZ (D65) -> ACEScg = kXyzToAp1 * kBradfordD65ToAcesWhite, the
// inverse of OCIO's builtin "UTILITY - ACES-AP1_to_CIE-XYZ-D65_BFD".
#pragma once

#include "schema/scatter/rgb.h"  // kAcescgLuminance

#include <Imath/ImathVec.h>

#include <array>

namespace opal {

// Acts on column vectors: out[i] = sum_j m[i][j] v[j].
using ColorMatrix = std::array<std::array<double, 3>, 3>;

// XYZ (ACES white) -> AP1, no adaptation: the inverse of AP1's RGB -> XYZ (each primary's
// XYZ scaled so that RGB (1, 1, 1) is the white with Y = 1), from the primaries (0.713,
// 0.293), (0.165, 0.830), (0.128, 0.044) and white of Academy S-2014-004 (ACEScg); the ACES
// reference CTL computes its XYZ_2_AP1_MAT the same way. Evaluated to 10 decimals.
inline constexpr ColorMatrix kXyzToAp1 = {{{1.6410233797, -0.3248032942, -0.2364246952},
                                           {-0.6636628587, 1.6153315917, 0.0167563477},
                                           {0.0117218943, -0.0082844420, 0.9883948585}}};

// Bradford chromatic adaptation (Lam 1985 cone matrix, von Kries scaling) from D65
// (0.3127, 0.3290) to the ACES white (0.32168, 0.33767): B^-1 diag(B w_aces / B w_d65) B
// with B = (0.8951 0.2664 -0.1614; -0.7502 1.7135 0.0367; 0.0389 -0.0685 1.0296).
inline constexpr ColorMatrix kBradfordD65ToAcesWhite = {{{1.0130349146, 0.0061052578, -0.0149709436},
                                                         {0.0076982301, 0.9981633521, -0.0050320385},
                                                         {-0.0028413174, 0.0046851567, 0.9245061375}}};


constexpr ColorMatrix product(const ColorMatrix& a, const ColorMatrix& b) {
    ColorMatrix m{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) m[i][j] += a[i][k] * b[k][j];
    return m;
}

constexpr Imath::V3d transform(const ColorMatrix& m, const Imath::V3d& v) {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

// XYZ (D65) -> ACEScg: (1.6605853264 -0.3152955609 -0.2415093276;
// -0.6599260632 1.6083914696 0.0172985948; 0.0090025691 -0.0035668764 0.9136433128).
inline constexpr ColorMatrix kXyzD65ToAcescg = product(kXyzToAp1, kBradfordD65ToAcesWhite);

}  // namespace opal
