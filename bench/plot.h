// Minimal chart drawing on an OpenImageIO ImageBuf for benchmark figures: panels with
// linear or log axes, tick marks, curves and markers. Text (titles, tick labels, legends)
// is drawn only when OpenImageIO finds a font; without one the figure keeps its tick
// marks and colours and is still readable against the CSV/JSON numbers.
#pragma once

#include <OpenImageIO/imagebuf.h>

#include <array>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace opal::bench {

using Color = std::array<float, 3>;

struct Axis {
    double min = 0.0, max = 1.0;
    bool log = false;            // log10 scale; min and max must be positive
    std::vector<double> ticks;   // data values with a tick mark (and a label if text works)
    std::string label;
};

// Decade ticks 10^k for min <= 10^k <= max.
std::vector<double> decadeTicks(double min, double max);

// A white RGB image with optional text.
class Canvas {
public:
    Canvas(int width, int height);
    bool hasText() const { return !font_.empty() || fontDefault_; }
    void line(int x0, int y0, int x1, int y1, const Color& color, int thickness = 1);
    void box(int x0, int y0, int x1, int y1, const Color& color, bool fill);
    enum class Align { Left, Center, Right };
    // Draws text with its baseline at y; does nothing when no font was found.
    void text(int x, int y, std::string_view text, int size, const Color& color, Align align = Align::Left);
    // 8-bit PNG (or whatever the extension says), written atomically. Throws on failure.
    void write(const std::filesystem::path& path) const;

private:
    OIIO::ImageBuf image_;
    std::string font_;
    bool fontDefault_ = false;
};

// A plotting area of a canvas with its data ranges.
class Panel {
public:
    Panel(Canvas& canvas, int x0, int y0, int x1, int y1, Axis x, Axis y);
    // Frame, zero line (linear y), ticks, tick labels, axis labels and the title.
    void drawAxes(std::string_view title);
    void curve(std::span<const double> xs, std::span<const double> ys, const Color& color, int thickness = 2);
    void marker(double x, double y, const Color& color, int radius = 4);
    // A legend entry (short line + label) at row `row` of the top-right corner.
    void legend(int row, std::string_view label, const Color& color);

private:
    double toPixelX(double x) const;
    double toPixelY(double y) const;
    Canvas& canvas_;
    int x0_, y0_, x1_, y1_;
    Axis x_, y_;
};

}  // namespace opal::bench
