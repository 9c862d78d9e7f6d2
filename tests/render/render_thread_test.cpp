// The render thread's controls (delegate/render_thread.h), with a callback that only counts
// and checks in: restarts, stops and pauses from the host thread in any order.
#include "delegate/render_thread.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <future>
#include <thread>

namespace opal {
namespace {

// Runs `work` on its own thread; a hang fails the test (and ends the process: the hung
// thread cannot be joined).
template <typename Work>
void withinSeconds(int seconds, Work work) {
    auto done = std::async(std::launch::async, work);
    if (done.wait_for(std::chrono::seconds(seconds)) != std::future_status::ready) {
        ADD_FAILURE() << "did not finish within " << seconds << " s";
        std::_Exit(1);
    }
    done.get();
}

TEST(RenderThread, StopRightAfterStartNeverWaitsForever) {
    std::atomic<int> runs{0};
    RenderThread thread([&] { ++runs; });
    withinSeconds(20, [&] {
        for (int i = 0; i < 20000; ++i) {
            thread.startRender();
            thread.stopRender();  // often before the thread picked the start up
            EXPECT_FALSE(thread.isRendering());
        }
    });
    // A start nobody stops runs the callback (the stops above may all have come first).
    const int before = runs.load();
    thread.startRender();
    withinSeconds(10, [&] {
        while (runs.load() == before) std::this_thread::yield();
    });
}

TEST(RenderThread, ARestartEndsTheRunningCallbackAtItsCheckpoint) {
    std::atomic<int> started{0}, checkpoints{0};
    RenderThread* self = nullptr;
    RenderThread thread([&] {
        ++started;
        while (!self->checkpoint()) ++checkpoints;
    });
    self = &thread;
    thread.startRender();
    while (checkpoints < 10) std::this_thread::yield();
    thread.startRender();  // the running callback returns, then runs again
    while (started < 2) std::this_thread::yield();
    withinSeconds(10, [&] { thread.stopRender(); });
    EXPECT_EQ(started.load(), 2);
    EXPECT_FALSE(thread.isRendering());
}

TEST(RenderThread, APausedCallbackWaitsAtItsCheckpointUntilResumed) {
    std::atomic<int> checkpoints{0};
    RenderThread* self = nullptr;
    RenderThread thread([&] {
        while (!self->checkpoint()) ++checkpoints;
    });
    self = &thread;
    thread.startRender();
    while (checkpoints < 10) std::this_thread::yield();
    thread.pauseRender();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    const int paused = checkpoints.load();
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    EXPECT_LE(checkpoints.load(), paused + 1);  // at most the checkpoint it was in
    thread.resumeRender();
    while (checkpoints < paused + 100) std::this_thread::yield();
    thread.pauseRender();
    withinSeconds(10, [&] { thread.stopRender(); });  // a paused callback stops too
}

}  // namespace
}  // namespace opal
