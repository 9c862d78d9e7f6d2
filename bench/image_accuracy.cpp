#include "bench/image_accuracy.h"

#include "schema/error.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace opal::bench {

namespace {

Imath::V3d rgb(std::span<const float> image, std::size_t pixel) {
    return {image[3 * pixel], image[3 * pixel + 1], image[3 * pixel + 2]};
}

// (r, g) / (r + g + b); (1/3, 1/3) for black.
Imath::V2d chromaticity(const Imath::V3d& c) {
    const double sum = c.x + c.y + c.z;
    if (!(std::abs(sum) > 0.0)) return {1.0 / 3.0, 1.0 / 3.0};
    return {c.x / sum, c.y / sum};
}

Percentiles percentilesOf(std::vector<double> values) {
    return {percentile(values, 0.5), percentile(values, 0.95)};
}

}  // namespace

double percentile(std::span<double> values, double p) {
    if (values.empty()) return 0.0;
    const std::size_t rank = std::min(values.size() - 1, std::size_t(std::ceil(p * double(values.size()))) - (p > 0.0));
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(rank), values.end());
    return values[rank];
}

ImageAccuracy measureAccuracy(std::span<const float> engine, std::span<const float> reference,
                              const Imath::V3d& luminance) {
    return measureAccuracy(engine, reference, std::vector<std::uint8_t>(reference.size() / 3, 1), luminance);
}

ImageAccuracy measureAccuracy(std::span<const float> engine, std::span<const float> reference,
                              std::span<const std::uint8_t> mask, const Imath::V3d& luminance) {
    if (engine.size() != reference.size() || engine.size() != 3 * mask.size())
        throw Error("image accuracy: engine (" + std::to_string(engine.size()) + " floats), reference (" +
                    std::to_string(reference.size()) + ") and mask (" + std::to_string(mask.size()) +
                    " pixels) do not match");
    ImageAccuracy result;
    double differenceSquared = 0.0, referenceSquared = 0.0;
    std::size_t negative = 0;
    double lowest = 0.0;
    std::vector<std::size_t> asset;
    std::vector<double> referenceY;
    for (std::size_t p = 0; p < mask.size(); ++p) {
        if (!mask[p]) continue;
        const Imath::V3d a = rgb(engine, p), b = rgb(reference, p);
        differenceSquared += (a - b).length2();
        referenceSquared += b.length2();
        negative += a.x < 0.0 || a.y < 0.0 || a.z < 0.0;
        lowest = std::min({lowest, a.x, a.y, a.z});
        asset.push_back(p);
        referenceY.push_back(b.dot(luminance));
    }
    if (asset.empty()) throw Error("image accuracy: no pixel shows the asset");
    result.pixels = asset.size();
    result.relativeRmse = referenceSquared > 0.0 ? std::sqrt(differenceSquared / referenceSquared) : 0.0;
    result.negativeFraction = double(negative) / double(asset.size());

    std::vector<double> sortedY = referenceY;
    const double p99 = percentile(sortedY, 0.99);
    const double threshold = 0.01 * p99;
    result.deepestNegative = p99 > 0.0 ? lowest / p99 : lowest;
    std::vector<std::pair<double, std::size_t>> bright;  // (reference Y, pixel)
    for (std::size_t i = 0; i < asset.size(); ++i)
        if (referenceY[i] >= threshold && referenceY[i] > 0.0) bright.emplace_back(referenceY[i], asset[i]);
    result.measured = bright.size();
    std::sort(bright.begin(), bright.end());
    std::vector<double> errors, darker, chroma;
    for (std::size_t i = 0; i < bright.size(); ++i) {
        const auto [y, p] = bright[i];
        const Imath::V3d a = rgb(engine, p), b = rgb(reference, p);
        const double error = std::abs(a.dot(luminance) - y) / y;
        errors.push_back(error);
        if (i < bright.size() / 2) darker.push_back(error);
        const Imath::V2d ca = chromaticity(a), cb = chromaticity(b);
        chroma.push_back(std::abs(ca.x - cb.x) + std::abs(ca.y - cb.y));
    }
    result.luminance = percentilesOf(errors);
    result.darkerHalf = percentilesOf(darker);
    result.chromaticity = percentilesOf(chroma);
    return result;
}

}  // namespace opal::bench
