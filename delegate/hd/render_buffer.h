// An AOV buffer (Hydra's HdRenderBuffer): width x height pixels of `channels` floats,
// row-major, row 0 at the top of the image.
#pragma once

#include "delegate/hd/prim.h"

#include <span>
#include <vector>

namespace opal::hd {

class RenderBuffer : public Bprim {
public:
    using Bprim::Bprim;

    void allocate(int width, int height, int channels) {
        width_ = width;
        height_ = height;
        channels_ = channels;
        data_.assign(std::size_t(width) * height * channels, 0.0f);
    }
    void sync(const SceneDelegate&, DirtyBits* bits) override { *bits = Dirty::Clean; }

    int width() const { return width_; }
    int height() const { return height_; }
    int channels() const { return channels_; }
    std::span<float> data() { return data_; }
    std::span<const float> data() const { return data_; }
    float* pixel(int x, int y) { return data_.data() + (std::size_t(y) * width_ + x) * channels_; }
    const float* pixel(int x, int y) const { return data_.data() + (std::size_t(y) * width_ + x) * channels_; }

private:
    int width_ = 0, height_ = 0, channels_ = 0;
    std::vector<float> data_;
};

}  // namespace opal::hd
