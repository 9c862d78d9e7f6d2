// Step 7 of the bake: per sample, the environment vectors of Ng et al. 2003 over the texels w
// of a cube map (schema/asset/cube_map.h), as occluded residuals
//   O_m(w) = (1 - V(x, w)) max(0, n.w) P_m(n.w) dOmega(w)
// (V the visible fraction of the texel, 2 x 2 rays per texel), Haar transformed per face, the
// largest terms kept. The delegate forms E_m = U_m(n) - <O_m, L> with U_m the dome's
// unoccluded hemisphere integral at the sample's normal (docs/ARCHITECTURE.md#dome-light):
// a sample that sees its whole hemisphere needs no term, and the terms a partly shadowed one
// keeps describe only its shadow. The m = 0 vector chooses the kept positions, shared by all
// m; P_m are the Fresnel moment polynomials of schema/scatter/fresnel_moments.h, so the
// delegate applies F_t(eta, .) for any eta.
#pragma once

#include "bake/progress.h"
#include "schema/asset/translucent_asset.h"

#include <span>

namespace opal {

struct VisibilitySettings {
    std::uint32_t cubeFaceSize = 32;
    // Per sample, the fewest terms whose dropped energy is at most error^2 times the energy
    // of an open hemisphere's m = 0 vector (so the dropped terms hold about `error` of an
    // open sample's E under a smooth dome), and at most `terms`. Measured on the 4,096-sample
    // bunny under the studio dome against the 64^2 brute-force reference, per-sample
    // luminance error p95: 0.005 -> 2.5% with 361 terms on average (the candle: 1.1%, 82
    // terms); the earlier 128 visible-transport terms: 28.6% (18.7%).
    std::uint32_t terms = 1024;
    double error = 0.005;
    std::uint32_t fresnelTerms = 2;
    // Schlick: the two-term fit of F_t is ten times closer than Legendre's
    // (schema/scatter/fresnel_moments.h); measured on the 4,096-sample candle's dome image
    // against the brute-force reference, relative RMSE 1.7% (Legendre: 3.5%).
    FresnelBasis fresnelBasis = FresnelBasis::Schlick;
};

EnvironmentTransfer buildEnvironmentTransfer(const RenderMesh& mesh, std::span<const SurfaceSample> samples,
                                             const VisibilitySettings& settings, ProgressSink* progress,
                                             const CancelToken& cancel);

}  // namespace opal
