#include "bench/random_outputs.h"

#include <algorithm>
#include <numeric>
#include <random>

namespace opal::bench {

namespace {

constexpr std::uint32_t kOutputSeed = 1;

}  // namespace

std::vector<std::uint32_t> randomOutputs(std::size_t samples, std::size_t count) {
    if (count == 0 || count >= samples) return {};
    std::vector<std::uint32_t> all(samples);
    std::iota(all.begin(), all.end(), 0u);
    std::mt19937 random(kOutputSeed);
    std::shuffle(all.begin(), all.end(), random);
    all.resize(count);
    std::sort(all.begin(), all.end());
    return all;
}

}  // namespace opal::bench
