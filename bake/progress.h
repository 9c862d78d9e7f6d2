// Progress and cancellation for long bake stages. A stage has a name and a total amount of
// work; workers report completed units from any thread. ProgressBar draws a bar with stage,
// percent and ETA on a terminal, prints plain start/end lines when not a TTY, and nothing
// when quiet. Cancellation is cooperative: stages poll a CancelToken between work items.
#pragma once

#include "schema/error.h"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <string>
#include <string_view>

namespace opal {

class ProgressSink {
public:
    virtual ~ProgressSink() = default;
    virtual void beginStage(std::string_view name, std::uint64_t total) = 0;
    virtual void advance(std::uint64_t units) = 0;  // thread-safe
    virtual void endStage() = 0;
};

// Thrown when a bake is interrupted; the bake writes nothing after it.
class Cancelled : public Error {
public:
    Cancelled() : Error("bake interrupted") {}
};

class CancelToken {
public:
    CancelToken() = default;
    explicit CancelToken(const std::atomic<bool>* flag) : flag_(flag) {}
    bool requested() const { return flag_ && flag_->load(std::memory_order_relaxed); }
    void throwIfRequested() const {
        if (requested()) throw Cancelled();
    }

private:
    const std::atomic<bool>* flag_ = nullptr;
};

enum class ProgressStyle { Quiet, Lines, Bar };

class ProgressBar final : public ProgressSink {
public:
    // Bar when `stream` is a terminal, Lines otherwise; Quiet when `quiet`.
    static ProgressStyle styleFor(std::FILE* stream, bool quiet);
    ProgressBar(std::FILE* stream, ProgressStyle style);
    ~ProgressBar() override;

    void beginStage(std::string_view name, std::uint64_t total) override;
    void advance(std::uint64_t units) override;
    void endStage() override;

private:
    using Clock = std::chrono::steady_clock;
    void draw(bool force);

    std::FILE* stream_;
    ProgressStyle style_;
    std::string stage_;
    std::uint64_t total_ = 0;
    std::atomic<std::uint64_t> done_{0};
    Clock::time_point start_{}, lastDraw_{};
    std::mutex drawMutex_;
    bool inStage_ = false;
};

// Runs a stage on a sink that may be null.
class StageScope {
public:
    StageScope(ProgressSink* sink, std::string_view name, std::uint64_t total) : sink_(sink) {
        if (sink_) sink_->beginStage(name, total);
    }
    ~StageScope() {
        if (sink_) sink_->endStage();
    }
    void advance(std::uint64_t units) const {
        if (sink_) sink_->advance(units);
    }
    StageScope(const StageScope&) = delete;
    StageScope& operator=(const StageScope&) = delete;

private:
    ProgressSink* sink_;
};

}  // namespace opal
