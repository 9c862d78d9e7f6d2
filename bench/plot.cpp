#include "bench/plot.h"

#include "schema/usd/atomic_file.h"

#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace opal::bench {

namespace {

constexpr Color kAxisColor = {0.15f, 0.15f, 0.15f};
constexpr Color kGridColor = {0.88f, 0.88f, 0.88f};

std::string tickLabel(double value, bool log) {
    char buffer[32];
    if (log && (value < 1e-2 || value > 1e3))
        std::snprintf(buffer, sizeof buffer, "1e%d", static_cast<int>(std::lround(std::log10(value))));
    else
        std::snprintf(buffer, sizeof buffer, "%g", value);
    return buffer;
}

// Position of v along the axis in [0, 1]; values outside the range (and log of v <= 0)
// land on the nearer edge so curves stay inside their panel.
double axisPosition(const Axis& a, double v) {
    const double t = a.log ? (std::log10(v) - std::log10(a.min)) / (std::log10(a.max) - std::log10(a.min))
                           : (v - a.min) / (a.max - a.min);
    if (!(t > 0.0)) return 0.0;  // also NaN
    return std::min(t, 1.0);
}

}  // namespace

std::vector<double> decadeTicks(double min, double max) {
    std::vector<double> ticks;
    for (int e = static_cast<int>(std::ceil(std::log10(min) - 1e-9)); std::pow(10.0, e) <= max * (1 + 1e-9); ++e)
        ticks.push_back(std::pow(10.0, e));
    return ticks;
}

Canvas::Canvas(int width, int height) : image_(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT)) {
    const float white[3] = {1.0f, 1.0f, 1.0f};
    OIIO::ImageBufAlgo::fill(image_, white);
    // OpenImageIO searches its font paths and the system's; probe the default font and
    // a common one, and go without text when neither is found.
    if (OIIO::ImageBufAlgo::text_size("0", 14).defined())
        fontDefault_ = true;
    else if (OIIO::ImageBufAlgo::text_size("0", 14, "DejaVuSans").defined())
        font_ = "DejaVuSans";
}

void Canvas::line(int x0, int y0, int x1, int y1, const Color& color, int thickness) {
    for (int t = 0; t < thickness; ++t) {
        const int o = t - thickness / 2;
        const bool steep = std::abs(y1 - y0) > std::abs(x1 - x0);
        OIIO::ImageBufAlgo::render_line(image_, x0 + (steep ? o : 0), y0 + (steep ? 0 : o), x1 + (steep ? o : 0),
                                        y1 + (steep ? 0 : o), color);
    }
}

void Canvas::box(int x0, int y0, int x1, int y1, const Color& color, bool fill) {
    OIIO::ImageBufAlgo::render_box(image_, x0, y0, x1, y1, color, fill);
}

void Canvas::text(int x, int y, std::string_view text, int size, const Color& color, Align align) {
    if (!hasText()) return;
    const auto alignX = align == Align::Left     ? OIIO::ImageBufAlgo::TextAlignX::Left
                        : align == Align::Center ? OIIO::ImageBufAlgo::TextAlignX::Center
                                                 : OIIO::ImageBufAlgo::TextAlignX::Right;
    OIIO::ImageBufAlgo::render_text(image_, x, y, text, size, font_, color, alignX);
}

void Canvas::write(const std::filesystem::path& path) const {
    writeAtomically(path, [&](const std::filesystem::path& tmp) {
        if (!image_.write(tmp.string(), OIIO::TypeDesc::UINT8)) throw std::runtime_error(image_.geterror());
    });
}

Panel::Panel(Canvas& canvas, int x0, int y0, int x1, int y1, Axis x, Axis y)
    : canvas_(canvas), x0_(x0), y0_(y0), x1_(x1), y1_(y1), x_(std::move(x)), y_(std::move(y)) {}

double Panel::toPixelX(double x) const { return x0_ + axisPosition(x_, x) * (x1_ - x0_); }
double Panel::toPixelY(double y) const { return y1_ - axisPosition(y_, y) * (y1_ - y0_); }

void Panel::drawAxes(std::string_view title) {
    for (double t : x_.ticks) {
        const int px = static_cast<int>(std::lround(toPixelX(t)));
        canvas_.line(px, y0_, px, y1_, kGridColor);
        canvas_.line(px, y1_, px, y1_ + 7, kAxisColor);
        canvas_.text(px, y1_ + 24, tickLabel(t, x_.log), 14, kAxisColor, Canvas::Align::Center);
    }
    for (double t : y_.ticks) {
        const int py = static_cast<int>(std::lround(toPixelY(t)));
        canvas_.line(x0_, py, x1_, py, kGridColor);
        canvas_.line(x0_ - 7, py, x0_, py, kAxisColor);
        canvas_.text(x0_ - 10, py + 5, tickLabel(t, y_.log), 14, kAxisColor, Canvas::Align::Right);
    }
    if (!y_.log && y_.min < 0.0 && y_.max > 0.0) {
        const int py = static_cast<int>(std::lround(toPixelY(0.0)));
        canvas_.line(x0_, py, x1_, py, kAxisColor);
    }
    canvas_.box(x0_, y0_, x1_, y1_, kAxisColor, false);
    canvas_.text((x0_ + x1_) / 2, y1_ + 48, x_.label, 16, kAxisColor, Canvas::Align::Center);
    canvas_.text(x0_, y0_ - 32, y_.label, 16, kAxisColor, Canvas::Align::Left);
    canvas_.text((x0_ + x1_) / 2, y0_ - 10, title, 18, kAxisColor, Canvas::Align::Center);
}

void Panel::curve(std::span<const double> xs, std::span<const double> ys, const Color& color, int thickness) {
    for (std::size_t i = 1; i < std::min(xs.size(), ys.size()); ++i) {
        canvas_.line(static_cast<int>(std::lround(toPixelX(xs[i - 1]))), static_cast<int>(std::lround(toPixelY(ys[i - 1]))),
                     static_cast<int>(std::lround(toPixelX(xs[i]))), static_cast<int>(std::lround(toPixelY(ys[i]))),
                     color, thickness);
    }
}

void Panel::marker(double x, double y, const Color& color, int radius) {
    const int px = static_cast<int>(std::lround(toPixelX(x))), py = static_cast<int>(std::lround(toPixelY(y)));
    canvas_.box(px - radius, py - radius, px + radius, py + radius, color, true);
}

void Panel::legend(int row, std::string_view label, const Color& color) {
    const int y = y0_ + 20 + 22 * row;
    canvas_.line(x1_ - 90, y, x1_ - 60, y, color, 3);
    canvas_.text(x1_ - 52, y + 5, label, 15, kAxisColor, Canvas::Align::Left);
}

}  // namespace opal::bench
