// What the compressed transfer means, as code: the run-time product of
// docs/ARCHITECTURE.md#compression (the paper's equation (10)):
//   wE  = w0 E                 Haar, per chart, of the irradiance at the samples
//   y_k = (w1 T_k w0^-1) wE    one sparse product per basis function
//   L   = w1^-1 (sum_k s_k y_k) CDF 9/7 inverse, per chart
// (L still lacks the (1/pi) F_t(eta, w_o) factor, applied per pixel.)
#pragma once

#include "schema/asset/translucent_asset.h"

#include <span>
#include <vector>

namespace opal {

// One channel, start to finish: returns sum_k s[k] (T_k E) at every sample (grid order).
std::vector<float> applyTransfer(const CompressedTransfer& transfer, const ChartLayout& layout,
                                 std::span<const double> s, std::span<const float> irradiance);

}  // namespace opal
