#include "bench/error_time_plot.h"

#include "bench/plot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace opal::bench {

namespace {

constexpr std::array<Color, 4> kColors = {Color{0.10f, 0.35f, 0.80f}, Color{0.80f, 0.10f, 0.15f},
                                          Color{0.90f, 0.45f, 0.05f}, Color{0.15f, 0.60f, 0.25f}};

bool plottable(const ErrorTimePoint& p) { return p.ms > 0.0 && p.error > 0.0 && std::isfinite(p.ms + p.error); }

// The whole decades around [lo, hi]; one decade when there is nothing to show.
Axis decadeAxis(double lo, double hi, std::string label) {
    if (!(lo <= hi)) lo = hi = 1.0;
    Axis a;
    a.log = true;
    a.min = std::pow(10.0, std::floor(std::log10(lo)));
    a.max = std::pow(10.0, std::ceil(std::log10(hi)));
    if (a.max <= a.min) a.max = 10.0 * a.min;
    a.ticks = decadeTicks(a.min, a.max);
    a.label = std::move(label);
    return a;
}

}  // namespace

void writeErrorTimePlot(const std::filesystem::path& file, const std::vector<ErrorTimeSeries>& series,
                        std::string_view title) {
    double msLo = std::numeric_limits<double>::infinity(), msHi = -msLo, errLo = msLo, errHi = -msLo;
    for (const ErrorTimeSeries& s : series)
        for (const ErrorTimePoint& p : s.points)
            if (plottable(p)) {
                msLo = std::min(msLo, p.ms), msHi = std::max(msHi, p.ms);
                errLo = std::min(errLo, p.error), errHi = std::max(errHi, p.error);
            }
    Canvas canvas(1120, 700);
    Panel panel(canvas, 110, 70, 840, 600, decadeAxis(msLo, msHi, "time of a point-light move (ms)"),
                decadeAxis(errLo, errHi, "relative RMSE against the exact gather"));
    panel.drawAxes(title);
    for (std::size_t i = 0; i < series.size(); ++i) {
        const Color& color = kColors[i % kColors.size()];
        std::vector<ErrorTimePoint> points;
        std::copy_if(series[i].points.begin(), series[i].points.end(), std::back_inserter(points), plottable);
        std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.ms < b.ms; });
        std::vector<double> xs, ys;
        for (const ErrorTimePoint& p : points) {
            xs.push_back(p.ms), ys.push_back(p.error);
            panel.marker(p.ms, p.error, color);
        }
        if (series[i].joined) panel.curve(xs, ys, color);
        panel.legend(int(i), series[i].label, color);
    }
    canvas.write(file);
}

}  // namespace opal::bench
