// The preview a USD host without Opal shows of a baked asset: primvars:displayColor per
// render vertex, in linear Rec.709 (what USD renderers assume of displayColor), of the
// asset under a documented default light (docs/ARCHITECTURE.md#display-color):
//
//   a uniform white dome of radiance 1 in ACEScg, seen through the asset's own baked
//   visibility; a sample i receives E_i = sum over the cube map of V mu dOmega (the m = 0
//   environment vector summed: n times each face's Haar DC term), pi where no visibility
//   was baked; the subsurface answer is the default material's total diffuse reflectance,
//   L_i = R_total(alpha', eta) E_i / pi per channel (Fresnel transmission and the transfer's
//   spread left out); a vertex takes its samples' weighted mean; ACEScg -> Rec.709.
//
// So an unoccluded vertex shows the material's diffuse albedo, and a concave one darker.
#pragma once

#include "schema/asset/translucent_asset.h"

#include <Imath/ImathVec.h>

#include <vector>

namespace opal {

// One colour per render vertex; empty when the asset has no vertex weights (made in
// memory without samples).
std::vector<Imath::V3f> displayColors(const TranslucentAsset& asset);

// ACEScg (AP1, ACES white) to linear Rec.709 (D65): XYZ(D65) -> Rec.709 after the inverse of
// kXyzD65ToAcescg, so that ACEScg white (1, 1, 1) is Rec.709 white.
Imath::V3d rec709FromAcescg(const Imath::V3d& acescg);

}  // namespace opal
