#include "delegate/render_thread.h"

namespace opal {

RenderThread::RenderThread(std::function<void()> render) : render_(std::move(render)), thread_([this] { loop(); }) {}

RenderThread::~RenderThread() {
    {
        std::lock_guard lock(mutex_);
        terminate_ = true;
        stopRequested_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

void RenderThread::loop() {
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait(lock, [this] { return terminate_ || startRequested_; });
        if (terminate_) return;
        startRequested_ = false;
        stopRequested_ = false;
        running_ = true;
        lock.unlock();
        render_();
        lock.lock();
        running_ = false;
        idle_.notify_all();
    }
}

void RenderThread::startRender() {
    {
        std::lock_guard lock(mutex_);
        startRequested_ = true;
        stopRequested_ = true;  // a running callback ends at its next checkpoint; loop() clears it
    }
    wake_.notify_all();
}

void RenderThread::stopRender() {
    std::unique_lock lock(mutex_);
    startRequested_ = false;
    stopRequested_ = true;
    wake_.notify_all();
    idle_.wait(lock, [this] { return !running_; });
}

void RenderThread::pauseRender() {
    std::lock_guard lock(mutex_);
    paused_ = true;
}

void RenderThread::resumeRender() {
    {
        std::lock_guard lock(mutex_);
        paused_ = false;
    }
    wake_.notify_all();
}

bool RenderThread::isPaused() const {
    std::lock_guard lock(mutex_);
    return paused_;
}

bool RenderThread::isRendering() const {
    std::lock_guard lock(mutex_);
    return running_ || startRequested_;
}

bool RenderThread::checkpoint() {
    std::unique_lock lock(mutex_);
    wake_.wait(lock, [this] { return !paused_ || stopRequested_ || terminate_; });
    return stopRequested_ || terminate_;
}

bool RenderThread::stopRequested() const {
    std::lock_guard lock(mutex_);
    return stopRequested_ || terminate_;
}

}  // namespace opal
