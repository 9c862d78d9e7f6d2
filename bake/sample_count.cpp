#include "bake/sample_count.h"

#include "schema/error.h"

#include <algorithm>
#include <optional>
#include <sstream>

namespace opal {
namespace {

constexpr std::uint64_t kMinSamples = 16;
constexpr std::uint64_t kMaxSamples = std::uint64_t(1) << 31;  // sample indices are 32-bit

std::optional<ChartLayout> layoutFor(std::uint64_t samples) {
    if (samples < kMinSamples || samples > kMaxSamples) return std::nullopt;
    std::uint32_t log2Size = 0;
    while (log2Size < kMaxChartLog2Size && (std::uint64_t(1) << (2 * (log2Size + 1))) <= samples) ++log2Size;
    std::uint64_t cells = std::uint64_t(1) << (2 * log2Size);
    if (samples % cells != 0) return std::nullopt;
    return ChartLayout{std::uint32_t(samples / cells), log2Size};
}

std::string describe(std::uint64_t samples) {
    ChartLayout layout = *layoutFor(samples);
    std::ostringstream s;
    s << samples << " (" << layout.charts << " x " << layout.size() << " x " << layout.size() << ")";
    return s.str();
}

}  // namespace

ChartLayout chartLayoutForSampleCount(std::uint64_t samples) {
    if (std::optional<ChartLayout> layout = layoutFor(samples)) return *layout;
    std::ostringstream message;
    message << "sample count " << samples << " is not M x 4^n with charts of up to 64 x 64 (at least "
            << kMinSamples << ", at most " << kMaxSamples << ")";
    // Valid counts are at most 4096 apart, so the nearest ones are found by stepping.
    std::uint64_t below = std::min(samples, kMaxSamples + 1);
    while (below >= kMinSamples && !layoutFor(below)) --below;
    std::uint64_t above = std::max(samples, kMinSamples - 1);
    while (above <= kMaxSamples && !layoutFor(above)) ++above;
    message << "; nearby valid counts:";
    if (below >= kMinSamples) message << " " << describe(below);
    if (above <= kMaxSamples) message << (below >= kMinSamples ? "," : "") << " " << describe(above);
    throw Error(message.str());
}

}  // namespace opal
