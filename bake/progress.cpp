#include "bake/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace opal {

namespace {

std::string formatSeconds(double s) {
    if (!std::isfinite(s) || s < 0) return "--:--";
    const long total = std::lround(s);
    char buf[32];
    if (total >= 3600)
        std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
    else
        std::snprintf(buf, sizeof buf, "%02ld:%02ld", total / 60, total % 60);
    return buf;
}

}  // namespace

ProgressStyle ProgressBar::styleFor(std::FILE* stream, bool quiet) {
    if (quiet) return ProgressStyle::Quiet;
    return isatty(fileno(stream)) ? ProgressStyle::Bar : ProgressStyle::Lines;
}

ProgressBar::ProgressBar(std::FILE* stream, ProgressStyle style) : stream_(stream), style_(style) {}

ProgressBar::~ProgressBar() {
    if (inStage_) endStage();
}

void ProgressBar::beginStage(std::string_view name, std::uint64_t total) {
    std::lock_guard lock(drawMutex_);
    stage_ = name;
    total_ = std::max<std::uint64_t>(total, 1);
    done_ = 0;
    start_ = lastDraw_ = Clock::now();
    inStage_ = true;
    if (style_ == ProgressStyle::Lines) {
        std::fprintf(stream_, "opal-bake: %s...\n", stage_.c_str());
        std::fflush(stream_);
    }
}

void ProgressBar::advance(std::uint64_t units) {
    done_.fetch_add(units, std::memory_order_relaxed);
    if (style_ == ProgressStyle::Bar) draw(false);
}

void ProgressBar::endStage() {
    if (!inStage_) return;
    const double seconds = std::chrono::duration<double>(Clock::now() - start_).count();
    done_ = total_;
    if (style_ == ProgressStyle::Bar) {
        draw(true);
        std::lock_guard lock(drawMutex_);
        std::fprintf(stream_, "\n");
    } else if (style_ == ProgressStyle::Lines) {
        std::fprintf(stream_, "opal-bake: %s done in %.2f s\n", stage_.c_str(), seconds);
    }
    std::fflush(stream_);
    inStage_ = false;
}

// Redraws at most ten times a second; a worker that finds the lock taken skips drawing.
void ProgressBar::draw(bool force) {
    std::unique_lock lock(drawMutex_, std::try_to_lock);
    if (!lock.owns_lock()) return;
    const auto now = Clock::now();
    if (!force && now - lastDraw_ < std::chrono::milliseconds(100)) return;
    lastDraw_ = now;
    const double fraction = std::min(1.0, double(done_.load()) / double(total_));
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : -1.0;
    constexpr int width = 30;
    const int filled = int(fraction * width);
    std::string bar(filled, '#');
    bar.resize(width, '.');
    std::fprintf(stream_, "\r%-22s [%s] %5.1f%%  elapsed %s  ETA %s ", stage_.c_str(), bar.c_str(),
                 100.0 * fraction, formatSeconds(elapsed).c_str(), formatSeconds(eta).c_str());
    std::fflush(stream_);
}

}  // namespace opal
