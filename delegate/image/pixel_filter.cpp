#include "delegate/image/pixel_filter.h"

#include "schema/error.h"

#include <array>
#include <cmath>
#include <numbers>

namespace opal {

namespace {

const std::array<std::string_view, 2> Names = {"box", "blackmanHarris"};

// The 4-term Blackman-Harris window over t in [0, 1] (Harris 1978): 6e-5 at the ends, 1 at 0.5.
float blackmanHarris(float t) {
    constexpr double a0 = 0.35875, a1 = 0.48829, a2 = 0.14128, a3 = 0.01168;
    const double x = 2.0 * std::numbers::pi * t;
    return float(a0 - a1 * std::cos(x) + a2 * std::cos(2.0 * x) - a3 * std::cos(3.0 * x));
}

}  // namespace

float filterWeight(PixelFilter filter, const Imath::V2f& p) {
    if (filter == PixelFilter::Box) return 1.0f;
    return blackmanHarris(p.x) * blackmanHarris(p.y);
}

std::span<const std::string_view> pixelFilterNames() { return Names; }

std::string_view pixelFilterName(PixelFilter filter) { return Names[std::size_t(filter)]; }

PixelFilter parsePixelFilter(std::string_view name) {
    for (std::size_t i = 0; i < Names.size(); ++i)
        if (Names[i] == name) return PixelFilter(i);
    throw Error("pixel filter '" + std::string(name) + "' is not one of box, blackmanHarris");
}

}  // namespace opal
