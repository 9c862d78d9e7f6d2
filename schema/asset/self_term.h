// The transfer's self term when it is left to run time (SelfTerm::AtRunTime,
// docs/ARCHITECTURE.md#self-term): a sample gathers its own light over its own area, a
// disk of radius rho_o = sqrt(A_o / pi), with the exact dipole of the current material,
//     L(x_o) += (1/pi) R_disk(rho_o; sigma) E(x_o),
// instead of through the basis (whose fit is worst where the profile is narrowest: at the
// short end of the editable range nearly all the light a sample returns is its own).
#pragma once

#include "schema/asset/translucent_asset.h"
#include "schema/scatter/material.h"

#include <span>

namespace opal {

// out[3 o + c] = R_disk(rho_o; sigma_c) (dipoleDiskReflectance) for every sample, rho_o in
// mm. Samples of equal area (every bake's: A_i = area / N) share one evaluation per
// channel, so a material edit costs O(N) stores. Throws opal::Error when out.size() !=
// 3 x samples.size() or unitsPerMm is not positive and finite.
void selfTermReflectance(std::span<const SurfaceSample> samples, double unitsPerMm, const Material& material,
                         std::span<float> out);

// The radius in mm beyond which the asset's transfer matrices use the profile: the smallest
// sample's disk radius sqrt(A_o / pi) when the self term is left to run time, else 0 (the
// diagonal then uses the basis at r = 0). What ProfileProjection fits the profile beyond.
double profileFitRadius(const TranslucentAsset& asset);

}  // namespace opal
