#include "schema/wavelet/haar.h"

#include "schema/wavelet/nonstandard.h"

#include <numbers>

namespace opal {

namespace {

// The orthonormal Haar step on deinterleaved blocks (Stollnitz et al. 1995, section 2,
// normalized): (lo, hi) <- ((lo + hi) / sqrt 2, (lo - hi) / sqrt 2). The butterfly is its
// own inverse, so synthesis is the same arithmetic followed by re-interleaving.
struct HaarStep {
    template <typename T>
    static void butterfly(T* lo, T* hi, std::size_t half, std::size_t width) {
        const T invSqrt2 = T(1) / std::numbers::sqrt2_v<T>;
        const std::size_t n = half * width;
        for (std::size_t j = 0; j < n; ++j) {
            const T a = lo[j], b = hi[j];
            lo[j] = (a + b) * invSqrt2;
            hi[j] = (a - b) * invSqrt2;
        }
    }
    template <typename T>
    static void analyze(T* lo, T* hi, std::size_t half, std::size_t width) {
        butterfly(lo, hi, half, width);
    }
    template <typename T>
    static void synthesize(T* lo, T* hi, std::size_t half, std::size_t width) {
        butterfly(lo, hi, half, width);
    }
};

}  // namespace

template <typename T>
void haarForward2D(std::span<T> grid, std::uint32_t size, std::uint32_t channels) {
    wavelet_detail::checkGrid("haarForward2D", grid.size(), size, channels);
    wavelet_detail::analyzeNonstandard<HaarStep>(grid, size, channels, 1);
}

template <typename T>
void haarInverse2D(std::span<T> grid, std::uint32_t size, std::uint32_t channels) {
    wavelet_detail::checkGrid("haarInverse2D", grid.size(), size, channels);
    wavelet_detail::synthesizeNonstandard<HaarStep>(grid, size, channels, 1);
}

template <typename T>
void haarForwardCharts(std::span<T> data, const ChartLayout& layout, std::uint32_t channels) {
    wavelet_detail::checkCharts("haarForwardCharts", data.size(), layout, channels);
    wavelet_detail::analyzeCharts<HaarStep>(data, layout, channels, 1);
}

template <typename T>
void haarInverseCharts(std::span<T> data, const ChartLayout& layout, std::uint32_t channels) {
    wavelet_detail::checkCharts("haarInverseCharts", data.size(), layout, channels);
    wavelet_detail::synthesizeCharts<HaarStep>(data, layout, channels, 1);
}

template void haarForward2D<float>(std::span<float>, std::uint32_t, std::uint32_t);
template void haarInverse2D<float>(std::span<float>, std::uint32_t, std::uint32_t);
template void haarForwardCharts<float>(std::span<float>, const ChartLayout&, std::uint32_t);
template void haarInverseCharts<float>(std::span<float>, const ChartLayout&, std::uint32_t);
template void haarForward2D<double>(std::span<double>, std::uint32_t, std::uint32_t);
template void haarInverse2D<double>(std::span<double>, std::uint32_t, std::uint32_t);
template void haarForwardCharts<double>(std::span<double>, const ChartLayout&, std::uint32_t);
template void haarInverseCharts<double>(std::span<double>, const ChartLayout&, std::uint32_t);

}  // namespace opal
