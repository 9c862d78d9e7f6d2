// The specular layer over the subsurface term (docs/ARCHITECTURE.md#specular): a dielectric GGX
// microfacet lobe (Walter et al. 2007) with Smith height-correlated masking (Heitz 2014), weighted
// by the exact Fresnel reflectance F_r(eta, .) = 1 - F_t(eta, .), so that what the surface reflects
// is exactly what the subsurface term does not let in.
//
// Roughness r in [0, 1] is the artist's (UsdPreviewSurface) parameter: alpha = r^2.
//
// Analytic lights: L_s = f_s(l, v) (n.l) E_perp V, with the light's E_perp and a shadow ray.
// Dome lights (an approximation, documented in delegate/DELEGATE.md): the reflected
// radiance is the dome averaged over the GGX lobe's angular footprint around the mirror
// direction, times F_r(eta, n.v):  L_s = F_r(eta, n.v) L_dome(reflect(v, n), footprint).
// It ignores the lobe's shape, masking and occlusion (the dome is never shadowed in the
// reflection), and is exact for a mirror (r = 0) and for a uniform dome up to masking.
#pragma once

#include "delegate/image/fresnel_table.h"

#include <Imath/ImathVec.h>

namespace opal {

// F_r for light arriving from outside onto a medium of index eta, cos(theta) clamped to [0, 1].
double fresnelReflectance(double eta, double cosTheta);

// alpha = r^2, r clamped to [0, 1], alpha at least 1e-4 (a delta lobe cannot take point lights).
double ggxAlpha(double roughness);

// D(h): the GGX normal distribution, normalized so that integral D (n.h) dw_h = 1.
double ggxDistribution(double nDotH, double alpha);

// f_s(l, v) (n.l): the BRDF times the cosine. n, v (toward the viewer), l (toward the
// light) unit vectors. Zero when l or v is below the surface.
double ggxReflectance(const Imath::V3d& n, const Imath::V3d& v, const Imath::V3d& l, double alpha, double eta);
// The same with F_r from a table of F_t (fresnel_table.h: within 1e-5), for the pixel loop.
double ggxReflectance(const Imath::V3d& n, const Imath::V3d& v, const Imath::V3d& l, double alpha,
                      const FresnelTable& fresnel);

// The mirror direction of v about n (both unit): 2 (n.v) n - v.
Imath::V3d reflect(const Imath::V3d& v, const Imath::V3d& n);

// The angular width (radians) over which a dome is averaged for a lobe of this alpha: the
// reflected lobe is about twice as wide as the half-vector lobe, whose width is ~alpha.
double reflectionFootprint(double alpha);

}  // namespace opal
