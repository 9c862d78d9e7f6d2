// The error-against-time figure of `opal-bench relight --peer jensen-buhler --plot`: for a
// point-light move, each method's time (x, log) against its relative error to the exact
// reference (y, log); the engine's points come from bakes at several compression settings,
// the peer's from its maxError sweep, so a reader sees where each method stands.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace opal::bench {

struct ErrorTimePoint {
    double ms = 0.0;     // time of a point-light move
    double error = 0.0;  // relative RMSE against the exact gather
};

struct ErrorTimeSeries {
    std::string label;
    std::vector<ErrorTimePoint> points;
    bool joined = false;  // a curve through the points in order of time, else markers alone
};

// Writes the figure (PNG or what the extension says) atomically; points with a
// non-positive time or error cannot sit on log axes and are left out. Throws on failure.
void writeErrorTimePlot(const std::filesystem::path& file, const std::vector<ErrorTimeSeries>& series,
                        std::string_view title);

}  // namespace opal::bench
