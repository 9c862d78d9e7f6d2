// Two images compared channel by channel (same size and channel names), for the tests that
// hold a picture the viewer saved against the truth: opal-render on the scene it saved, or
// the same viewer before an edit that was undone; and measures of one picture (a channel's
// mean, the side the light falls on).
#pragma once

#include "tests/view/view_process.h"

#include <algorithm>
#include <cmath>

namespace opal::test {

// The largest |a - b| over every channel of every pixel (equal infinities count 0); +inf
// when the sizes or channels differ.
inline double maxDifference(const ReadImage& a, const ReadImage& b) {
    if (a.width != b.width || a.height != b.height || a.names != b.names || a.pixels.empty())
        return std::numeric_limits<double>::infinity();
    double worst = 0.0;
    std::size_t at = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        if (a.pixels[i] == b.pixels[i]) continue;
        const double d = std::abs(double(a.pixels[i]) - double(b.pixels[i]));
        if (d > worst) worst = d, at = i;
    }
    if (worst > 0.0) {
        const std::size_t channels = a.names.size(), pixel = at / channels;
        std::printf("  largest difference %g in %s at (%zu, %zu): %.8g vs %.8g\n", worst,
                    a.names[at % channels].c_str(), pixel % std::size_t(a.width), pixel / std::size_t(a.width),
                    double(a.pixels[at]), double(b.pixels[at]));
    }
    return worst;
}

// The mean of one channel over the image.
inline double channelMean(const ReadImage& image, const std::string& channel) {
    const int c = image.channel(channel);
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) sum += image.at(x, y, c);
    return sum / std::max(1, image.width * image.height);
}

// Where the light falls across the asset: the luminance-weighted mean x of the asset's
// pixels minus their plain mean x, in pixels (negative: brighter on the left).
inline double brightSide(const ReadImage& exr) {
    const int r = exr.channel("R"), g = exr.channel("G"), b = exr.channel("B"), a = exr.channel("A");
    double weighted = 0.0, weight = 0.0, plain = 0.0;
    int count = 0;
    for (int y = 0; y < exr.height; ++y)
        for (int x = 0; x < exr.width; ++x) {
            if (exr.at(x, y, a) < 0.999f) continue;
            const double luminance = 0.2126 * exr.at(x, y, r) + 0.7152 * exr.at(x, y, g) + 0.0722 * exr.at(x, y, b);
            weighted += luminance * x;
            weight += luminance;
            plain += x;
            ++count;
        }
    EXPECT_GT(weight, 0.0);
    return weighted / weight - plain / std::max(count, 1);
}

}  // namespace opal::test
