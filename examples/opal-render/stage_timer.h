// Wall-clock time per stage of a run, for opal-render's one-line summary.
#pragma once

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace opal::render {

class StageTimer {
public:
    // Ends the stage that ran since the previous lap (or construction) and names it.
    void lap(std::string stage) {
        const auto now = Clock::now();
        stages_.emplace_back(std::move(stage), std::chrono::duration<double>(now - last_).count());
        last_ = now;
    }
    // "load 0.12 s, sync 1.30 s, ..."
    std::string summary() const;

private:
    using Clock = std::chrono::steady_clock;
    Clock::time_point last_ = Clock::now();
    std::vector<std::pair<std::string, double>> stages_;
};

}  // namespace opal::render
