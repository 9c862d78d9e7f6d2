#include "bake/chart_parameterization.h"

#include "schema/error.h"

#include <Imath/ImathBox.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace opal {
namespace {

constexpr std::size_t kParallelSize = 4096;  // samples below which recursion stays serial

// The 3D directions (unit vectors) the grid's +u (axis 0) and +v (axis 1) point along in
// the part of the surface a quadtree node covers.
using Frame = std::array<Imath::V3f, 2>;

Imath::V3f unitAxis(int axis) {
    Imath::V3f e(0.0f);
    e[axis] = 1.0f;
    return e;
}

int shortestAxis(const Imath::Box3f& box) {
    Imath::V3f size = box.size();
    int axis = 0;
    for (int a = 1; a < 3; ++a) {
        if (size[a] < size[axis]) axis = a;
    }
    return axis;
}

int secondLongestAxis(const Imath::Box3f& box) {
    int longest = box.majorAxis(), shortest = shortestAxis(box);
    if (longest == shortest) return (longest + 1) % 3;  // a cube of points: any other axis
    return 3 - longest - shortest;
}

class ChartBuilder {
public:
    ChartBuilder(std::span<const Imath::V3f> positions, const ChartLayout& layout)
        : positions_(positions), layout_(layout), order_(positions.size()), grid_(positions.size()) {
        std::iota(order_.begin(), order_.end(), 0u);
    }

    std::vector<std::uint32_t> build() {
        splitCharts(0, order_.size(), 0, layout_.charts);
        return std::move(grid_);
    }

private:
    Imath::Box3f bounds(std::size_t begin, std::size_t end) const {
        Imath::Box3f box;
        for (std::size_t i = begin; i < end; ++i) box.extendBy(positions_[order_[i]]);
        return box;
    }

    // Puts the samples of [begin, mid) below those of [mid, end) along `axis`.
    void medianSplit(std::size_t begin, std::size_t mid, std::size_t end, int axis) {
        std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                         [&](std::uint32_t a, std::uint32_t b) {
                             float ca = positions_[a][axis], cb = positions_[b][axis];
                             return ca < cb || (ca == cb && a < b);
                         });
    }

    template <class A, class B>
    static void maybeParallel(std::size_t size, A a, B b) {
        if (size >= kParallelSize) {
            tbb::parallel_invoke(a, b);
        } else {
            a();
            b();
        }
    }

    void splitCharts(std::size_t begin, std::size_t end, std::uint32_t firstChart, std::uint32_t charts) {
        if (charts == 1) {
            buildChart(begin, end, firstChart);
            return;
        }
        std::uint32_t lowerCharts = charts / 2;
        std::size_t mid = begin + lowerCharts * layout_.cellsPerChart();
        medianSplit(begin, mid, end, bounds(begin, end).majorAxis());
        maybeParallel(
            end - begin, [&] { splitCharts(begin, mid, firstChart, lowerCharts); },
            [&] { splitCharts(mid, end, firstChart + lowerCharts, charts - lowerCharts); });
    }

    void buildChart(std::size_t begin, std::size_t end, std::uint32_t chart) {
        Imath::Box3f box = bounds(begin, end);
        Frame frame{unitAxis(box.majorAxis()), unitAxis(secondLongestAxis(box))};
        quadtree(begin, end, chart, {0, 0}, layout_.size(), frame);
    }

    Imath::V3f centroid(std::size_t begin, std::size_t end) const {
        Imath::V3d sum(0.0);
        for (std::size_t i = begin; i < end; ++i) sum += Imath::V3d(positions_[order_[i]]);
        return Imath::V3f(sum / double(end - begin));
    }

    // Splits a node of size x size cells into halves along one grid axis g, then each half
    // into quadrants (splitHalf). The split's direction d (from the lower half's centroid to
    // the upper's, which lies along the surface) goes to the grid axis whose frame
    // direction it is closer to, with the sign that agrees with the frame.
    void quadtree(std::size_t begin, std::size_t end, std::uint32_t chart, std::array<std::uint32_t, 2> cell,
                  std::uint32_t size, const Frame& frame) {
        if (size == 1) {
            grid_[chart * layout_.cellsPerChart() + std::size_t(cell[1]) * layout_.size() + cell[0]] = order_[begin];
            return;
        }
        int axis = bounds(begin, end).majorAxis();
        std::size_t mid = begin + (end - begin) / 2;
        medianSplit(begin, mid, end, axis);
        Imath::V3f d = (centroid(mid, end) - centroid(begin, mid)).normalized();
        int g = std::abs(d.dot(frame[0])) >= std::abs(d.dot(frame[1])) ? 0 : 1;
        bool lowerFirst = d.dot(frame[g]) >= 0.0f;
        Frame childFrame = frame;
        childFrame[g] = lowerFirst ? d : -d;
        Halves halves = order(begin, mid, end, lowerFirst);
        std::uint32_t half = size / 2;
        maybeParallel(
            end - begin,
            [&] { splitHalf(halves.first[0], halves.first[1], chart, cell, half, childFrame, g, 0, axis); },
            [&] {
                std::array<std::uint32_t, 2> next = cell;
                next[g] += half;
                splitHalf(halves.second[0], halves.second[1], chart, next, half, childFrame, g, 1, axis);
            });
    }

    // Splits one half of a node along the other grid axis h = 1 - g into two quadrants.
    // `side` is the half's index along g; `parentAxis` the spatial axis of the node's split.
    void splitHalf(std::size_t begin, std::size_t end, std::uint32_t chart, std::array<std::uint32_t, 2> cell,
                   std::uint32_t half, Frame frame, int g, int side, int parentAxis) {
        int h = 1 - g;
        int axis = bounds(begin, end).majorAxis();
        std::size_t mid = begin + (end - begin) / 2;
        medianSplit(begin, mid, end, axis);
        bool lowerFirst;
        if (axis == parentAxis) {
            // A strip: both splits run along it. Put the quarters next to the parent's
            // split plane second along h on both sides (a snake), so they stay neighbours.
            lowerFirst = (side == 0) == (frame[g][axis] >= 0.0f);
        } else {
            Imath::V3f d = (centroid(mid, end) - centroid(begin, mid)).normalized();
            lowerFirst = d.dot(frame[h]) >= 0.0f;
            frame[h] = lowerFirst ? d : -d;
        }
        Halves halves = order(begin, mid, end, lowerFirst);
        std::array<std::uint32_t, 2> next = cell;
        next[h] += half;
        maybeParallel(
            end - begin, [&] { quadtree(halves.first[0], halves.first[1], chart, cell, half, frame); },
            [&] { quadtree(halves.second[0], halves.second[1], chart, next, half, frame); });
    }

    // The two halves [begin, mid) and [mid, end) in grid order.
    struct Halves {
        std::array<std::size_t, 2> first, second;
    };
    static Halves order(std::size_t begin, std::size_t mid, std::size_t end, bool lowerFirst) {
        if (lowerFirst) return {{begin, mid}, {mid, end}};
        return {{mid, end}, {begin, mid}};
    }

    std::span<const Imath::V3f> positions_;
    ChartLayout layout_;
    std::vector<std::uint32_t> order_;  // samples, permuted in place by the splits
    std::vector<std::uint32_t> grid_;   // cell -> sample
};

}  // namespace

std::vector<std::uint32_t> parameterizeCharts(std::span<const Imath::V3f> positions, const ChartLayout& layout) {
    if (layout.charts == 0 || positions.size() != layout.cells()) {
        throw Error("chart parameterization: " + std::to_string(positions.size()) + " samples do not fill " +
                    std::to_string(layout.charts) + " charts of " + std::to_string(layout.size()) + " x " +
                    std::to_string(layout.size()) + " cells");
    }
    return ChartBuilder(positions, layout).build();
}

}  // namespace opal
