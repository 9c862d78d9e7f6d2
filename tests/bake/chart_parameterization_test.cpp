#include "bake/chart_parameterization.h"

#include "bake/random.h"
#include "bake/surface_sampler.h"
#include "schema/error.h"
#include "tests/bake/test_meshes.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace opal {
namespace {

std::vector<Imath::V3f> positionsOf(const SurfaceSampling& sampling) {
    std::vector<Imath::V3f> positions;
    for (const SurfaceSample& s : sampling.samples) positions.push_back(s.position);
    return positions;
}

void expectPermutation(const std::vector<std::uint32_t>& order, std::size_t n) {
    std::vector<std::uint32_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::uint32_t> identity(n);
    std::iota(identity.begin(), identity.end(), 0u);
    EXPECT_EQ(sorted, identity);
}

// Distances between the samples of horizontally and vertically adjacent cells.
std::vector<float> gridNeighbourDistances(const std::vector<Imath::V3f>& positions,
                                          const std::vector<std::uint32_t>& order, const ChartLayout& layout) {
    std::vector<float> distances;
    std::uint32_t size = layout.size();
    for (std::uint32_t chart = 0; chart < layout.charts; ++chart) {
        auto at = [&](std::uint32_t u, std::uint32_t v) {
            return positions[order[chart * layout.cellsPerChart() + v * size + u]];
        };
        for (std::uint32_t v = 0; v < size; ++v) {
            for (std::uint32_t u = 0; u < size; ++u) {
                if (u + 1 < size) distances.push_back((at(u, v) - at(u + 1, v)).length());
                if (v + 1 < size) distances.push_back((at(u, v) - at(u, v + 1)).length());
            }
        }
    }
    return distances;
}

float median(std::vector<float> values) {
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
}

TEST(ChartParameterization, RegularGridMapsOntoItself) {
    // A 32 x 32 lattice in a tilted plane, shuffled: the median splits recover the lattice,
    // so every pair of grid neighbours is a pair of lattice neighbours (distance 1).
    const int n = 32;
    Imath::V3f ex = Imath::V3f(1.0f, 0.0f, 0.0f), ey = Imath::V3f(0.0f, 0.6f, 0.8f);
    std::vector<Imath::V3f> positions;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) positions.push_back(float(i) * ex + float(j) * ey);
    Random random(3, 0);
    for (std::size_t i = positions.size() - 1; i > 0; --i) {
        std::swap(positions[i], positions[random.nextBits() % (i + 1)]);
    }
    ChartLayout layout{1, 5};
    std::vector<std::uint32_t> order = parameterizeCharts(positions, layout);
    expectPermutation(order, positions.size());
    for (float d : gridNeighbourDistances(positions, order, layout)) EXPECT_NEAR(d, 1.0f, 1e-5f);
}

TEST(ChartParameterization, SphereGridNeighboursAreSpatialNeighbours) {
    SurfaceSampling sampling = sampleSurface(test::sphereRenderMesh(4), 4096);
    std::vector<Imath::V3f> positions = positionsOf(sampling);
    float spacing = float(std::sqrt(sampling.surfaceArea / 4096.0));
    for (ChartLayout layout : {ChartLayout{1, 6}, ChartLayout{4, 5}, ChartLayout{16, 4}}) {
        std::vector<std::uint32_t> order = parameterizeCharts(positions, layout);
        expectPermutation(order, positions.size());
        std::vector<float> distances = gridNeighbourDistances(positions, order, layout);
        EXPECT_LE(median(distances), 2.5f * spacing) << layout.charts << " charts";
        // Most neighbours are close, not just half of them.
        std::sort(distances.begin(), distances.end());
        EXPECT_LE(distances[distances.size() * 9 / 10], 4.0f * spacing) << layout.charts << " charts";
    }
}

TEST(ChartParameterization, TorusWithAnyChartCount) {
    SurfaceSampling sampling = sampleSurface(test::torusRenderMesh(1.0f, 0.35f, 96, 48), 3 * 1024);
    std::vector<Imath::V3f> positions = positionsOf(sampling);
    float spacing = float(std::sqrt(sampling.surfaceArea / double(positions.size())));
    for (ChartLayout layout : {ChartLayout{3, 5}, ChartLayout{12, 4}}) {
        std::vector<std::uint32_t> order = parameterizeCharts(positions, layout);
        expectPermutation(order, positions.size());
        EXPECT_LE(median(gridNeighbourDistances(positions, order, layout)), 2.5f * spacing);
    }
}

TEST(ChartParameterization, ChartsAreCompactPatches) {
    // With 8 charts on a sphere each chart should be about an octant: its samples lie
    // within a cap much smaller than the sphere (radius below 1.2, vs 2 for the diameter).
    SurfaceSampling sampling = sampleSurface(test::sphereRenderMesh(4), 8 * 256);
    std::vector<Imath::V3f> positions = positionsOf(sampling);
    ChartLayout layout{8, 4};
    std::vector<std::uint32_t> order = parameterizeCharts(positions, layout);
    for (std::uint32_t chart = 0; chart < 8; ++chart) {
        Imath::V3f centre(0.0f);
        for (std::size_t c = 0; c < 256; ++c) centre += positions[order[chart * 256 + c]];
        centre /= 256.0f;
        float farthest = 0.0f;
        for (std::size_t c = 0; c < 256; ++c) farthest = std::max(farthest, (positions[order[chart * 256 + c]] - centre).length());
        EXPECT_LT(farthest, 1.2f) << "chart " << chart;
    }
}

TEST(ChartParameterization, DeterministicWhateverTheThreadCount) {
    SurfaceSampling sampling = sampleSurface(test::sphereRenderMesh(4), 16384 / 2);
    std::vector<Imath::V3f> positions = positionsOf(sampling);
    ChartLayout layout{2, 6};
    std::vector<std::uint32_t> a = parameterizeCharts(positions, layout), b;
    tbb::task_arena oneThread(1);
    oneThread.execute([&] { b = parameterizeCharts(positions, layout); });
    EXPECT_EQ(a, b);
}

TEST(ChartParameterization, RefusesMismatchedCounts) {
    std::vector<Imath::V3f> positions(100, Imath::V3f(0.0f));
    EXPECT_THROW(parameterizeCharts(positions, ChartLayout{1, 3}), Error);
    EXPECT_THROW(parameterizeCharts(positions, ChartLayout{0, 3}), Error);
}

}  // namespace
}  // namespace opal
