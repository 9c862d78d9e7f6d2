// Small helpers shared by the wavelet tests: reproducible random grids and norms.
#pragma once

#include "schema/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <span>
#include <string_view>
#include <vector>

namespace opal::test {

// Round-trip tolerance of a transform computed in float or double.
constexpr double tolerance(float) { return 1e-6; }
constexpr double tolerance(double) { return 1e-13; }

template <typename T>
std::vector<T> randomValues(std::size_t count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::vector<T> values(count);
    for (T& v : values) v = T(uniform(rng));
    return values;
}

template <typename T>
double energy(std::span<const T> values) {
    double sum = 0;
    for (T v : values) sum += double(v) * double(v);
    return sum;
}

// |a - b| / |b| in the L2 norm.
template <typename T>
double relativeError(std::span<const T> a, std::span<const T> b) {
    double diff = 0;
    for (std::size_t i = 0; i < a.size(); ++i) diff += std::pow(double(a[i]) - double(b[i]), 2);
    return std::sqrt(diff / energy(b));
}

// f() must throw opal::Error whose message contains `needle`.
template <typename F>
void expectErrorContaining(F f, std::string_view needle) {
    try {
        f();
        ADD_FAILURE() << "no opal::Error thrown; expected one mentioning \"" << needle << "\"";
    } catch (const Error& e) {
        EXPECT_NE(std::string_view(e.what()).find(needle), std::string_view::npos) << e.what();
    }
}

}  // namespace opal::test
