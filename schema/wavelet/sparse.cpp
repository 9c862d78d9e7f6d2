// Coefficient selection for the two compression steps (DESIGN.md section 5): step 1
// keeps the largest Haar coefficients of each transfer row, step 2 keeps the 9/7
// coefficients carrying a given fraction of the energy.
#include "schema/wavelet/sparse.h"

#include "schema/error.h"
#include "schema/wavelet/scratch.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

namespace opal {

namespace {

void checkLength(std::string_view function, std::size_t length) {
    if (length > std::numeric_limits<std::uint32_t>::max())
        throw Error(std::string(function) + ": " + std::to_string(length) +
                    " coefficients do not fit 32-bit indices");
}

void checkFinite(std::string_view function, std::string_view what, std::span<const float> values) {
    bool allFinite = true;
    for (float v : values) allFinite &= std::isfinite(v);  // no early exit: vectorizes
    if (allFinite) return;
    for (std::size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i]))
            throw Error(std::string(function) + ": " + std::string(what) + " " + std::to_string(i) +
                        " is not finite (" + std::to_string(values[i]) + ")");
}

// The k-th largest score (k >= 1) and how many of the k largest are strictly above it;
// the remaining k - above are ties at `value`, taken by lower index.
template <typename V>
struct Threshold {
    V value = 0;
    std::size_t above = 0;
};

// The coefficients with the k largest scores, ties at the threshold broken by lower
// index, in one ascending pass (so no sort of the result is needed).
template <typename V, typename Score>
SparseVector collect(std::span<const float> dense, Score score, Threshold<V> threshold,
                     std::size_t k) {
    SparseVector result;
    result.indices.reserve(k);
    result.values.reserve(k);
    std::size_t ties = k - threshold.above;
    for (std::uint32_t i = 0; i < dense.size(); ++i) {
        const V s = score(i);
        bool take = s > threshold.value;
        if (!take && s == threshold.value && ties > 0) {
            take = true;
            --ties;
        }
        if (take) {
            result.indices.push_back(i);
            result.values.push_back(dense[i]);
        }
    }
    return result;
}

// The threshold of the k largest values once values[0, k) holds them (in any order).
template <typename V>
Threshold<V> thresholdOfTop(std::span<const V> values, std::size_t k) {
    const V kth = *std::min_element(values.begin(), values.begin() + k);
    return {kth, std::size_t(std::count_if(values.begin(), values.begin() + k,
                                           [&](V v) { return v > kth; }))};
}

// Reorder `values` (all > 0) so that its first k entries are the k largest, for the
// smallest k whose sum reaches `target`; return k and the threshold. Halving selection
// with std::nth_element on contiguous values: expected O(n), no full sort.
std::pair<std::size_t, Threshold<double>> selectFewestReaching(std::span<double> values,
                                                               double target) {
    constexpr std::size_t kSortBelow = 64;
    const auto larger = std::greater<double>();
    std::size_t lo = 0, hi = values.size();  // values[0, lo) are taken; k is in (lo, hi]
    double need = target;
    while (hi - lo > kSortBelow) {
        const std::size_t mid = lo + (hi - lo) / 2;
        std::nth_element(values.begin() + lo, values.begin() + mid, values.begin() + hi, larger);
        const double upper = std::accumulate(values.begin() + lo, values.begin() + mid, 0.0);
        if (upper >= need) {
            hi = mid;
        } else {
            need -= upper;
            lo = mid;
        }
    }
    std::sort(values.begin() + lo, values.begin() + hi, larger);
    std::size_t k = hi;  // if rounding keeps `need` above 0, everything left is needed
    for (std::size_t j = lo; j < hi; ++j) {
        need -= values[j];
        if (need <= 0) {
            k = j + 1;
            break;
        }
    }
    return {k, thresholdOfTop<double>(values, k)};
}

}  // namespace

SparseVector keepLargest(std::span<const float> dense, std::size_t n) {
    checkLength("keepLargest", dense.size());
    std::span<float> magnitudes = wavelet_detail::threadScratch<float>(dense.size());
    std::size_t nonZeros = 0;
    bool allFinite = true;
    for (std::uint32_t i = 0; i < dense.size(); ++i) {
        magnitudes[i] = std::abs(dense[i]);
        nonZeros += magnitudes[i] != 0.0f;
        allFinite &= magnitudes[i] <= std::numeric_limits<float>::max();  // false for NaN
    }
    if (!allFinite) checkFinite("keepLargest", "coefficient", dense);  // throws, naming it
    auto magnitude = [&](std::uint32_t i) { return std::abs(dense[i]); };
    if (n >= nonZeros) return collect(dense, magnitude, Threshold<float>{0.0f, nonZeros}, nonZeros);
    if (n == 0) return {};

    // The n-th largest magnitude (> 0, since n < nonZeros) by selection.
    std::nth_element(magnitudes.begin(), magnitudes.begin() + (n - 1), magnitudes.end(),
                     std::greater<float>());
    return collect(dense, magnitude, thresholdOfTop<float>(magnitudes, n), n);
}

SparseVector keepEnergyFraction(std::span<const float> dense, double fraction,
                                std::span<const float> normsSquared) {
    checkLength("keepEnergyFraction", dense.size());
    if (!(fraction >= 0.0 && fraction <= 1.0))
        throw Error("keepEnergyFraction: fraction " + std::to_string(fraction) +
                    " is not in [0, 1]");
    if (!normsSquared.empty() && normsSquared.size() != dense.size())
        throw Error("keepEnergyFraction: " + std::to_string(normsSquared.size()) + " norms for " +
                    std::to_string(dense.size()) + " coefficients");
    checkFinite("keepEnergyFraction", "coefficient", dense);
    checkFinite("keepEnergyFraction", "norm", normsSquared);
    for (std::size_t i = 0; i < normsSquared.size(); ++i)
        if (normsSquared[i] < 0.0f)
            throw Error("keepEnergyFraction: norm " + std::to_string(i) + " is negative");

    // e_i = c_i^2 g_i, in double so that sums of many small energies stay accurate.
    auto energy = [&](std::uint32_t i) {
        const double c = dense[i];
        return c * c * (normsSquared.empty() ? 1.0 : double(normsSquared[i]));
    };
    std::span<double> energies = wavelet_detail::threadScratch<double>(dense.size());
    std::size_t count = 0;
    for (std::uint32_t i = 0; i < dense.size(); ++i)
        if (const double e = energy(i); e > 0.0) energies[count++] = e;
    energies = energies.first(count);
    if (fraction == 0.0 || count == 0) return {};
    if (fraction == 1.0) return collect(dense, energy, Threshold<double>{0.0, count}, count);

    const double total = std::accumulate(energies.begin(), energies.end(), 0.0);
    const auto [k, threshold] = selectFewestReaching(energies, fraction * total);
    return collect(dense, energy, threshold, k);
}

}  // namespace opal
