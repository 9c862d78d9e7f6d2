// The delegate's render thread (Hydra's HdRenderThread): one background thread that runs the
// render callback when asked, and the controls a host needs while it runs. The callback calls
// checkpoint() between tiles: that is where a restart, a stop or a pause takes effect, so a
// host never waits longer than one tile, and a paused render sleeps on a condition variable
// (no CPU) until resumed.
#pragma once

#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace opal {

class RenderThread {
public:
    // `render` runs on the thread once per startRender (a restart requested while it runs ends
    // it at its next checkpoint and runs it again).
    explicit RenderThread(std::function<void()> render);
    ~RenderThread();  // stops the render and joins the thread
    RenderThread(const RenderThread&) = delete;
    RenderThread& operator=(const RenderThread&) = delete;

    // Runs the callback (again): a running one ends at its next checkpoint first. Returns at once.
    void startRender();
    // Ends the running callback at its next checkpoint and waits until it returned (a paused
    // one too); nothing runs until the next startRender.
    void stopRender();
    // A paused callback waits in its next checkpoint until resume or stop.
    void pauseRender();
    void resumeRender();
    bool isPaused() const;
    // Whether the callback is running (or about to).
    bool isRendering() const;

    // For the callback, between tiles: waits while paused; true when it must return now (a
    // restart, a stop or the destructor asked for it).
    bool checkpoint();
    // The same without waiting: whether a restart, a stop or the destructor was asked for.
    bool stopRequested() const;

private:
    void loop();

    std::function<void()> render_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;   // startRender, resume, stop, terminate
    std::condition_variable idle_;   // the callback returned
    bool startRequested_ = false, stopRequested_ = false, paused_ = false, terminate_ = false;
    bool running_ = false;  // the callback is executing (a start may be pending besides)
    std::thread thread_;  // last: starts after the members it uses
};

}  // namespace opal
