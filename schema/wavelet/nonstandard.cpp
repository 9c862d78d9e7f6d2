#include "schema/wavelet/nonstandard.h"

#include "schema/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <bit>
#include <string>

namespace opal::wavelet_detail {

namespace {

constexpr std::uint32_t kMaxSize = 1u << 16;
constexpr std::uint32_t kMaxChannels = 1u << 16;
// Below this many values per call, TBB task overhead outweighs the work.
constexpr std::size_t kParallelValues = std::size_t(1) << 15;

void checkChannels(std::string_view function, std::uint32_t channels) {
    if (channels == 0 || channels > kMaxChannels)
        throw Error(std::string(function) + ": channels must be in [1, " +
                    std::to_string(kMaxChannels) + "], got " + std::to_string(channels));
}

}  // namespace

void checkGrid(std::string_view function, std::size_t values, std::uint32_t size,
               std::uint32_t channels) {
    if (!std::has_single_bit(size) || size > kMaxSize)
        throw Error(std::string(function) + ": grid size " + std::to_string(size) +
                    " is not a power of two in [1, " + std::to_string(kMaxSize) + "]");
    checkChannels(function, channels);
    const std::size_t expected = std::size_t(size) * size * channels;
    if (values != expected)
        throw Error(std::string(function) + ": grid has " + std::to_string(values) +
                    " values, expected " + std::to_string(size) + " x " + std::to_string(size) +
                    " x " + std::to_string(channels) + " channels = " + std::to_string(expected));
}

void checkCharts(std::string_view function, std::size_t values, const ChartLayout& layout,
                 std::uint32_t channels) {
    if (layout.log2Size > 16)
        throw Error(std::string(function) + ": chart layout log2Size " +
                    std::to_string(layout.log2Size) + " is larger than 16");
    checkChannels(function, channels);
    const std::size_t expected = layout.cells() * channels;
    if (values != expected)
        throw Error(std::string(function) + ": data has " + std::to_string(values) +
                    " values, expected " + std::to_string(layout.charts) + " charts x " +
                    std::to_string(layout.size()) + " x " + std::to_string(layout.size()) + " x " +
                    std::to_string(channels) + " channels = " + std::to_string(expected));
}

void forEachChart(const ChartLayout& layout, std::uint32_t channels,
                  const std::function<void(std::uint32_t chart)>& transformChart) {
    if (layout.charts < 2 || layout.cells() * channels < kParallelValues) {
        for (std::uint32_t chart = 0; chart < layout.charts; ++chart) transformChart(chart);
        return;
    }
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, layout.charts),
                      [&](const tbb::blocked_range<std::uint32_t>& charts) {
                          for (std::uint32_t chart = charts.begin(); chart != charts.end(); ++chart)
                              transformChart(chart);
                      });
}

}  // namespace opal::wavelet_detail
