// The CDF 9/7 lifting steps on a deinterleaved buffer (`half` low blocks, then `half`
// high blocks, each `width` values), shared by the 1D and 2D transforms. Internal to
// schema/wavelet; see cdf97.h for the conventions and references.
#pragma once

#include <cstddef>

namespace opal::wavelet_detail {

// Daubechies and Sweldens (1998), the (9-7) example of section 7; JPEG 2000 Part 1, Annex F.
struct Cdf97Constants {
    static constexpr double alpha = -1.586134342059924;
    static constexpr double beta = -0.052980118572961;
    static constexpr double gamma = 0.882911075530934;
    static constexpr double delta = 0.443506852043971;
    static constexpr double zeta = 1.149604398860241;
};

// Both steps need half >= 1 (a signal of at least 2 samples).
//
// Predict: high[l] += a (low[l] + low[l+1]). At the right end low[half] is the mirror
// image of low[half-1] (x[n] = x[n-2] under whole-sample symmetry).
template <typename T>
void liftHigh(const T* lo, T* hi, std::size_t half, std::size_t width, T a) {
    const std::size_t interior = (half - 1) * width;
    for (std::size_t j = 0; j < interior; ++j) hi[j] += a * (lo[j] + lo[j + width]);
    for (std::size_t j = interior; j < half * width; ++j) hi[j] += T(2) * a * lo[j];
}

// Update: low[l] += b (high[l-1] + high[l]). At the left end high[-1] is the mirror image
// of high[0] (x[-1] = x[1]).
template <typename T>
void liftLow(T* lo, const T* hi, std::size_t half, std::size_t width, T b) {
    for (std::size_t j = 0; j < width; ++j) lo[j] += T(2) * b * hi[j];
    for (std::size_t j = width; j < half * width; ++j) lo[j] += b * (hi[j - width] + hi[j]);
}

template <typename T>
void scale(T* values, std::size_t count, T factor) {
    for (std::size_t j = 0; j < count; ++j) values[j] *= factor;
}

struct Cdf97Step {
    using C = Cdf97Constants;

    template <typename T>
    static void analyze(T* lo, T* hi, std::size_t half, std::size_t width) {
        liftHigh(lo, hi, half, width, T(C::alpha));
        liftLow(lo, hi, half, width, T(C::beta));
        liftHigh(lo, hi, half, width, T(C::gamma));
        liftLow(lo, hi, half, width, T(C::delta));
        scale(lo, half * width, T(C::zeta));
        scale(hi, half * width, T(1 / C::zeta));
    }

    // The lifting steps undone in reverse order with negated coefficients.
    template <typename T>
    static void synthesize(T* lo, T* hi, std::size_t half, std::size_t width) {
        scale(lo, half * width, T(1 / C::zeta));
        scale(hi, half * width, T(C::zeta));
        liftLow(lo, hi, half, width, T(-C::delta));
        liftHigh(lo, hi, half, width, T(-C::gamma));
        liftLow(lo, hi, half, width, T(-C::beta));
        liftHigh(lo, hi, half, width, T(-C::alpha));
    }
};

}  // namespace opal::wavelet_detail
