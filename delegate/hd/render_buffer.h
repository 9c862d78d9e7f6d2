// An AOV buffer (Hydra's HdRenderBuffer): width x height pixels of `channels` floats,
// row-major, row 0 at the top of the image.
//
// Threads: a render thread writes tiles while the host reads. map() locks the buffer for
// reading and unmap() releases it; tiles are written whole under writeTiles(), which waits
// while the buffer is mapped, so a mapped buffer never shows part of a tile. Writers of
// different tiles do not wait for each other. allocate() waits for readers too; data() and
// pixel() are for when nothing renders into the buffer (once converged or stopped).
#pragma once

#include "delegate/hd/prim.h"

#include <atomic>
#include <mutex>
#include <shared_mutex>
#include <span>
#include <vector>

namespace opal::hd {

class RenderBuffer : public Bprim {
public:
    using Bprim::Bprim;

    // Every channel of every pixel = clearValue; not converged. Waits while the buffer is
    // mapped (a host's reader never sees it change size under it).
    void allocate(int width, int height, int channels, float clearValue = 0.0f) {
        std::unique_lock lock(mutex_);
        width_ = width;
        height_ = height;
        channels_ = channels;
        data_.assign(std::size_t(width) * height * channels, clearValue);
        converged_ = false;
    }
    void sync(const SceneDelegate&, DirtyBits* bits) override { *bits = Dirty::Clean; }
    DirtyBits initialDirtyBits() const override { return Dirty::Clean; }

    int width() const { return width_; }
    int height() const { return height_; }
    int channels() const { return channels_; }

    // Hydra's Map/Unmap: the pixels, consistent until unmap(). Every map() needs its unmap().
    const float* map() const {
        mutex_.lock();
        return data_.data();
    }
    void unmap() const { mutex_.unlock(); }
    // map() .. unmap() for a scope.
    class Mapped {
    public:
        explicit Mapped(const RenderBuffer& b) : buffer_(b), data_(b.map()) {}
        ~Mapped() { buffer_.unmap(); }
        Mapped(const Mapped&) = delete;
        Mapped& operator=(const Mapped&) = delete;
        std::span<const float> data() const { return {data_, buffer_.data_.size()}; }
        const float* pixel(int x, int y) const { return data_ + (std::size_t(y) * buffer_.width_ + x) * buffer_.channels_; }
    private:
        const RenderBuffer& buffer_;
        const float* data_;
    };

    // For render delegates: write(pixels) may write any part of the buffer; a map() waits
    // until it returns.
    template <typename Write>
    void writeTiles(Write&& write) {
        std::shared_lock lock(mutex_);
        write(data_.data());
    }
    // Whether the values are final (the render pass reached its sample count).
    bool isConverged() const { return converged_.load(std::memory_order_acquire); }
    void setConverged(bool converged) { converged_.store(converged, std::memory_order_release); }

    std::span<float> data() { return data_; }
    std::span<const float> data() const { return data_; }
    float* pixel(int x, int y) { return data_.data() + (std::size_t(y) * width_ + x) * channels_; }
    const float* pixel(int x, int y) const { return data_.data() + (std::size_t(y) * width_ + x) * channels_; }

private:
    int width_ = 0, height_ = 0, channels_ = 0;
    std::vector<float> data_;
    // Readers (map) hold it exclusively, tile writers shared: writers of disjoint tiles
    // run together, and a reader never sees a tile half written.
    mutable std::shared_mutex mutex_;
    std::atomic<bool> converged_{false};
};

}  // namespace opal::hd
