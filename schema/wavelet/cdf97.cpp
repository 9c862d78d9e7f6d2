#include "schema/wavelet/cdf97.h"

#include "schema/error.h"
#include "schema/wavelet/cdf97_lifting.h"
#include "schema/wavelet/nonstandard.h"

#include <algorithm>
#include <string>

namespace opal {

namespace {

using wavelet_detail::Cdf97Step;

void checkEvenLength(std::string_view function, std::size_t length) {
    if (length < 2 || length % 2 != 0)
        throw Error(std::string(function) + ": signal length " + std::to_string(length) +
                    " is not an even number >= 2");
}

}  // namespace

std::uint32_t cdf97CoarsestSize(std::uint32_t size) {
    return size <= 1 ? 1 : std::min(kCdf97CoarsestSize, size / 2);
}

template <typename T>
void cdf97AnalysisStep1D(std::span<T> signal) {
    checkEvenLength("cdf97AnalysisStep1D", signal.size());
    const std::size_t half = signal.size() / 2;
    std::span<T> scratch = wavelet_detail::threadScratch<T>(signal.size());
    wavelet_detail::deinterleave(signal.data(), 1, 1, signal.size(), scratch.data());
    Cdf97Step::analyze(scratch.data(), scratch.data() + half, half, 1);
    std::copy(scratch.begin(), scratch.end(), signal.begin());
}

template <typename T>
void cdf97SynthesisStep1D(std::span<T> signal) {
    checkEvenLength("cdf97SynthesisStep1D", signal.size());
    const std::size_t half = signal.size() / 2;
    std::span<T> scratch = wavelet_detail::threadScratch<T>(signal.size());
    std::copy(signal.begin(), signal.end(), scratch.begin());
    Cdf97Step::synthesize(scratch.data(), scratch.data() + half, half, 1);
    wavelet_detail::interleave(scratch.data(), signal.data(), 1, 1, signal.size());
}

template <typename T>
void cdf97Forward2D(std::span<T> grid, std::uint32_t size, std::uint32_t channels) {
    wavelet_detail::checkGrid("cdf97Forward2D", grid.size(), size, channels);
    wavelet_detail::analyzeNonstandard<Cdf97Step>(grid, size, channels, cdf97CoarsestSize(size));
}

template <typename T>
void cdf97Inverse2D(std::span<T> grid, std::uint32_t size, std::uint32_t channels) {
    wavelet_detail::checkGrid("cdf97Inverse2D", grid.size(), size, channels);
    wavelet_detail::synthesizeNonstandard<Cdf97Step>(grid, size, channels, cdf97CoarsestSize(size));
}

template <typename T>
void cdf97ForwardCharts(std::span<T> data, const ChartLayout& layout, std::uint32_t channels) {
    wavelet_detail::checkCharts("cdf97ForwardCharts", data.size(), layout, channels);
    wavelet_detail::analyzeCharts<Cdf97Step>(data, layout, channels,
                                             cdf97CoarsestSize(layout.size()));
}

template <typename T>
void cdf97InverseCharts(std::span<T> data, const ChartLayout& layout, std::uint32_t channels) {
    wavelet_detail::checkCharts("cdf97InverseCharts", data.size(), layout, channels);
    wavelet_detail::synthesizeCharts<Cdf97Step>(data, layout, channels,
                                                cdf97CoarsestSize(layout.size()));
}

template void cdf97AnalysisStep1D<float>(std::span<float>);
template void cdf97SynthesisStep1D<float>(std::span<float>);
template void cdf97Forward2D<float>(std::span<float>, std::uint32_t, std::uint32_t);
template void cdf97Inverse2D<float>(std::span<float>, std::uint32_t, std::uint32_t);
template void cdf97ForwardCharts<float>(std::span<float>, const ChartLayout&, std::uint32_t);
template void cdf97InverseCharts<float>(std::span<float>, const ChartLayout&, std::uint32_t);
template void cdf97AnalysisStep1D<double>(std::span<double>);
template void cdf97SynthesisStep1D<double>(std::span<double>);
template void cdf97Forward2D<double>(std::span<double>, std::uint32_t, std::uint32_t);
template void cdf97Inverse2D<double>(std::span<double>, std::uint32_t, std::uint32_t);
template void cdf97ForwardCharts<double>(std::span<double>, const ChartLayout&, std::uint32_t);
template void cdf97InverseCharts<double>(std::span<double>, const ChartLayout&, std::uint32_t);

}  // namespace opal
