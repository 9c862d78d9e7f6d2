// Step 7 of the bake: per sample, the environment transport vectors of Ng et al. 2003,
// T_m(w) = V(x, w) max(0, n.w) P_m(n.w) dOmega(w) over the texels w of a cube map
// (schema/asset/cube_map.h), Haar transformed per face, the largest terms kept. The m = 0
// vector chooses the kept positions, shared by all m; P_m are the shifted Legendre
// polynomials of schema/scatter/fresnel_moments.h, so the delegate applies F_t(eta, .)
// for any eta (docs/ARCHITECTURE.md#dome-light).
#pragma once

#include "bake/progress.h"
#include "schema/asset/translucent_asset.h"

#include <span>

namespace opal {

struct VisibilitySettings {
    std::uint32_t cubeFaceSize = 32;
    std::uint32_t terms = 128;
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
