// What a person dragging a control sees, measured: interface frames per second, new
// pictures per second that show an edit (not redraws of an old one), and the time from
// an edit to the first picture that shows it.
#pragma once

#include <chrono>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace opal::view {

class EditLatency {
public:
    using Clock = std::chrono::steady_clock;

    explicit EditLatency(Clock::time_point start) : start_(start) {}

    void frame() { ++frames_; }
    // An edit went to the render session as submission `number`.
    void edited(int number, Clock::time_point when);
    // A picture showing every submission up to `applied` is on screen: the first one
    // for each newer submission counts.
    void shown(int applied, Clock::time_point when);

    // "interface 58.1 fps, 31.0 new pictures/s, edit to picture median 24 ms (max 61),
    // N edits in S s": the rates over the drag, [start, the last new picture] (or [start,
    // end] when none was shown), not over the wait for convergence after it.
    std::string summary(Clock::time_point end) const;

private:
    Clock::time_point start_;
    int frames_ = 0, pictures_ = 0, lastShown_ = 0;
    int framesAtLastPicture_ = 0;
    std::optional<Clock::time_point> lastPicture_;
    std::map<int, Clock::time_point> pending_;  // edits not shown yet, by submission
    std::vector<double> latenciesMs_;
    int edits_ = 0;
};

}  // namespace opal::view
