#include "examples/opal-view/core/edit_latency.h"

#include <algorithm>
#include <cstdio>

namespace opal::view {

void EditLatency::edited(int number, Clock::time_point when) {
    pending_[number] = when;
    ++edits_;
}

void EditLatency::shown(int applied, Clock::time_point when) {
    if (applied <= lastShown_) return;
    lastShown_ = applied;
    ++pictures_;
    lastPicture_ = when;
    framesAtLastPicture_ = frames_;
    // The picture shows the newest edit it took in; the older ones it skipped are merged.
    const auto newest = pending_.find(applied);
    if (newest != pending_.end())
        latenciesMs_.push_back(std::chrono::duration<double, std::milli>(when - newest->second).count());
    pending_.erase(pending_.begin(), pending_.upper_bound(applied));
}

std::string EditLatency::summary(Clock::time_point end) const {
    const double seconds = std::max(std::chrono::duration<double>(lastPicture_.value_or(end) - start_).count(), 1e-9);
    const int frames = lastPicture_ ? framesAtLastPicture_ : frames_;
    std::vector<double> sorted = latenciesMs_;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted.empty() ? 0.0 : sorted[sorted.size() / 2];
    const double worst = sorted.empty() ? 0.0 : sorted.back();
    char text[256];
    std::snprintf(text, sizeof text,
                  "interface %.1f fps, %.1f new pictures/s, edit to picture median %.0f ms (max %.0f), %d edits in %.1f s",
                  frames / seconds, pictures_ / seconds, median, worst, edits_, seconds);
    return text;
}

}  // namespace opal::view
