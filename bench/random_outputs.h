// A fixed random subset of an asset's samples, for exact gathers that cost O(N) per output:
// the reference of `opal-bench relight` and the replays of `opal-bench error-sources` are
// measured at these outputs when every one of N would take minutes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace opal::bench {

// `count` distinct samples of [0, samples) drawn uniformly (fixed seed), ascending; empty
// (meaning every sample) when count is 0 or not below samples.
std::vector<std::uint32_t> randomOutputs(std::size_t samples, std::size_t count);

}  // namespace opal::bench
