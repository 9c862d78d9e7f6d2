#include "examples/opal-view/core/picture_converter.h"

#include <tbb/task_arena.h>

namespace opal::view {

namespace {

// Each block x block block's mean (the last row and column of blocks average what they have).
Image reduced(const Image& image, int block) {
    if (image.empty() || block <= 1) return image;
    Image out((image.width() + block - 1) / block, (image.height() + block - 1) / block, image.channels());
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x)
            for (int c = 0; c < image.channels(); ++c) {
                float sum = 0.0f;
                int count = 0;
                for (int dy = 0; dy < block && block * y + dy < image.height(); ++dy)
                    for (int dx = 0; dx < block && block * x + dx < image.width(); ++dx, ++count)
                        sum += image.at(block * x + dx, block * y + dy, c);
                out.at(x, y, c) = sum / float(count);
            }
    return out;
}

}  // namespace

PictureConverter::PictureConverter(const ColorConfig& config) : display_(config), thread_([this] { work(); }) {}

PictureConverter::~PictureConverter() {
    {
        std::lock_guard lock(mutex_);
        quit_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

bool PictureConverter::request(PictureRequest request) {
    {
        std::lock_guard lock(mutex_);
        if (queued_ || running_) return false;
        queued_ = std::move(request);
    }
    wake_.notify_all();
    return true;
}

bool PictureConverter::busy() const {
    std::lock_guard lock(mutex_);
    return queued_ || running_;
}

bool PictureConverter::ready() const {
    std::lock_guard lock(mutex_);
    return done_.has_value();
}

std::optional<ConvertedPicture> PictureConverter::take() {
    std::lock_guard lock(mutex_);
    std::optional<ConvertedPicture> done;
    done.swap(done_);
    return done;
}

void PictureConverter::drain() {
    std::unique_lock lock(mutex_);
    idle_.wait(lock, [this] { return !queued_ && !running_; });
}

void PictureConverter::work() {
    for (;;) {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [this] { return quit_ || queued_; });
        if (quit_) return;
        const PictureRequest request = std::move(*queued_);
        queued_.reset();
        running_ = true;
        lock.unlock();
        ConvertedPicture picture = convert(request);
        lock.lock();
        done_ = std::move(picture);
        running_ = false;
        idle_.notify_all();
    }
}

ConvertedPicture PictureConverter::convert(const PictureRequest& request) {
    ConvertedPicture picture{{}, request.tag, {}};
    try {
        if (request.display != display_.display() || request.view != display_.view())
            display_.setDisplayView(request.display, request.view);
        const Image mapped = mappedImage(*request.buffer);
        const Image linear = reduced(mapped, request.block);
        // Isolated: while its rows run, this thread must not pick up the renderer's tiles.
        tbb::this_task_arena::isolate([&] { picture.image = display_.toDisplay(linear, request.aov, request.grade); });
    } catch (const std::exception& e) {
        picture.error = e.what();
    }
    return picture;
}

}  // namespace opal::view
