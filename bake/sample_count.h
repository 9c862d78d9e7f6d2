// How many surface samples a bake takes, and how they split into charts: N = M x 4^n
// (docs/ARCHITECTURE.md#wavelet-domain). The rule: charts are as large as possible up to
// 64 x 64 (n <= 6, big enough for the Haar and CDF 9/7 transforms to compress, small enough
// that a chart stays a near-planar patch), so n = 6 once N >= 4096, else the largest n with
// 4^n <= N; M = N / 4^n must then be a whole number. So 16384 = 4 x 64 x 64,
// 65536 = 16 x 64 x 64, 262144 = 64 x 64 x 64, 1024 = 1 x 32 x 32, 3072 = 3 x 32 x 32. At
// least 16 samples.
#pragma once

#include "schema/wavelet/chart_layout.h"

#include <cstdint>

namespace opal {

inline constexpr std::uint32_t kMaxChartLog2Size = 6;

// The layout for `samples` samples; throws opal::Error naming the nearest valid counts
// below and above when `samples` does not fit the rule.
ChartLayout chartLayoutForSampleCount(std::uint64_t samples);

}  // namespace opal
