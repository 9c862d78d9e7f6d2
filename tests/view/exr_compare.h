// Two images compared channel by channel (same size and channel names), for the tests that
// hold a picture the viewer saved against the truth: opal-render on the scene it saved, or
// the same viewer before an edit that was undone.
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
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        if (a.pixels[i] == b.pixels[i]) continue;
        worst = std::max(worst, std::abs(double(a.pixels[i]) - double(b.pixels[i])));
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

}  // namespace opal::test
