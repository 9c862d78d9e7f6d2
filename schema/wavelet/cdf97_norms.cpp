// Squared norms of the CDF 9/7 synthesis basis functions (see cdf97.h).
//
// In the nonstandard decomposition, coefficient (r, c) belongs to the level whose block
// size s is the smallest power of two >= 2 * cdf97CoarsestSize(size) with r, c < s (the
// coarsest band belongs to the coarsest level). Its synthesis function is the
// 2D inverse step at size s applied to a unit impulse, followed by the inverse steps at
// 2s, ..., size; every one of these is a tensor product of the same 1D step on rows and
// columns, so the function is h_s(c) (x) h_s(r) with
//   h_s(i) = S_size ... S_2s S_s e_i   (e_i a unit impulse in a length-s signal,
//                                       S_m the 1D synthesis step on the first m values),
// and its squared norm is |h_s(r)|^2 |h_s(c)|^2. Boundary functions are included exactly.
#include "schema/wavelet/cdf97.h"

#include "schema/error.h"

#include <algorithm>
#include <bit>
#include <numeric>
#include <string>

namespace opal {

namespace {

// |h_s(i)|^2 for i in [0, s).
std::vector<double> levelNormsSquared(std::uint32_t s, std::uint32_t size) {
    std::vector<double> norms(s);
    std::vector<double> signal(size);
    for (std::uint32_t i = 0; i < s; ++i) {
        std::fill(signal.begin(), signal.end(), 0.0);
        signal[i] = 1.0;
        for (std::uint32_t m = s; m <= size; m *= 2)
            cdf97SynthesisStep1D(std::span<double>(signal).first(m));
        norms[i] = std::inner_product(signal.begin(), signal.end(), signal.begin(), 0.0);
    }
    return norms;
}

// The level block size s of coefficient (r, c): 2^(floor(log2 max(r, c)) + 1), at least
// the coarsest level's 2 * coarsest.
std::uint32_t levelOf(std::uint32_t r, std::uint32_t c, std::uint32_t coarsest) {
    return std::max(2 * coarsest, std::bit_floor(std::max(r, c)) * 2);
}

}  // namespace

std::vector<float> cdf97SynthesisNormsSquared(std::uint32_t size) {
    if (!std::has_single_bit(size) || size > (1u << 16))
        throw Error("cdf97SynthesisNormsSquared: grid size " + std::to_string(size) +
                    " is not a power of two in [1, 65536]");
    if (size == 1) return {1.0f};  // no transform: the identity
    const std::uint32_t coarsest = cdf97CoarsestSize(size);
    std::vector<std::vector<double>> levels(std::bit_width(size));  // indexed by log2(s)
    for (std::uint32_t s = 2 * coarsest; s <= size; s *= 2)
        levels[std::bit_width(s) - 1] = levelNormsSquared(s, size);

    std::vector<float> norms(std::size_t(size) * size);
    for (std::uint32_t r = 0; r < size; ++r)
        for (std::uint32_t c = 0; c < size; ++c) {
            const std::vector<double>& level = levels[std::bit_width(levelOf(r, c, coarsest)) - 1];
            norms[std::size_t(r) * size + c] = float(level[r] * level[c]);
        }
    return norms;
}

std::vector<float> cdf97SynthesisNormsSquared(const ChartLayout& layout) {
    if (layout.log2Size > 16)
        throw Error("cdf97SynthesisNormsSquared: chart layout log2Size " +
                    std::to_string(layout.log2Size) + " is larger than 16");
    const std::vector<float> chart = cdf97SynthesisNormsSquared(layout.size());
    std::vector<float> norms;
    norms.reserve(layout.cells());
    for (std::uint32_t c = 0; c < layout.charts; ++c)
        norms.insert(norms.end(), chart.begin(), chart.end());
    return norms;
}

}  // namespace opal
