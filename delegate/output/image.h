// A 2D float image with interleaved channels, row-major, top row first: the form render
// buffers hand to color conversion and to the EXR and preview writers.
#pragma once

#include "schema/error.h"

#include <algorithm>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace opal {

class Image {
public:
    Image() = default;

    // A zero-filled image. Throws opal::Error unless every dimension is positive.
    Image(int width, int height, int channels)
        : width_(width), height_(height), channels_(channels) {
        if (width <= 0 || height <= 0 || channels <= 0) {
            throw Error("Image: invalid size " + std::to_string(width) + "x" +
                        std::to_string(height) + " with " + std::to_string(channels) +
                        " channels (all must be positive)");
        }
        pixels_.assign(static_cast<std::size_t>(width) * height * channels, 0.0f);
    }

    // A copy of `pixels` (interleaved, row-major), e.g. a render buffer's data. Throws
    // opal::Error when the size does not match.
    Image(int width, int height, int channels, std::span<const float> pixels)
        : Image(width, height, channels) {
        if (pixels.size() != pixels_.size()) {
            throw Error("Image: " + std::to_string(pixels.size()) + " values given for " +
                        std::to_string(width) + "x" + std::to_string(height) + "x" +
                        std::to_string(channels));
        }
        std::copy(pixels.begin(), pixels.end(), pixels_.begin());
    }

    int width() const { return width_; }
    int height() const { return height_; }
    int channels() const { return channels_; }
    bool empty() const { return pixels_.empty(); }

    std::size_t rowFloats() const { return static_cast<std::size_t>(width_) * channels_; }

    float* row(int y) { return pixels_.data() + y * rowFloats(); }
    const float* row(int y) const { return pixels_.data() + y * rowFloats(); }

    float& at(int x, int y, int c) { return row(y)[static_cast<std::size_t>(x) * channels_ + c]; }
    float at(int x, int y, int c) const {
        return row(y)[static_cast<std::size_t>(x) * channels_ + c];
    }

    std::span<float> pixels() { return pixels_; }
    std::span<const float> pixels() const { return pixels_; }

private:
    int width_ = 0;
    int height_ = 0;
    int channels_ = 0;
    std::vector<float> pixels_;
};

}  // namespace opal
