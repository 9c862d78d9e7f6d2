// What the compressed transfer means, as code: the run-time product of
// docs/ARCHITECTURE.md#compression (the paper's equation (10)):
//   wE  = w0 E                 Haar, per chart, of the irradiance at the samples
//   y_k = (w1 T_k w0^-1) wE    one sparse product per basis function
//   L   = w1^-1 (sum_k s_k y_k) CDF 9/7 inverse, per chart
// (L still lacks the (1/pi) F_t(eta, w_o) factor, applied per pixel.) With the exact
// harmonic transfer (normal_harmonics.h), E is first split into sum_q a_q f_q and a
// residual R, and y_k = (w1 T_k w0^-1) (w0 R) + w1 sum_q a_q (T_k f_q).
#pragma once

#include "schema/asset/translucent_asset.h"

#include <span>
#include <vector>

namespace opal {

// One channel, start to finish: returns sum_k s[k] (T_k E) at every sample (grid order).
// samples: the asset's (their normals split E), required when transfer.harmonics is not
// empty. Throws opal::Error for mismatched sizes.
std::vector<float> applyTransfer(const CompressedTransfer& transfer, const ChartLayout& layout,
                                 std::span<const double> s, std::span<const float> irradiance,
                                 std::span<const SurfaceSample> samples = {});

}  // namespace opal
