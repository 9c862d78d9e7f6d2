#include "bake/vertex_welding.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace opal {
namespace {

bool lexicographicLess(const Imath::V3f& a, const Imath::V3f& b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
}

// A uniform grid over space with cells of the weld tolerance: a vertex's partners lie in
// its own cell or one of the 26 around it.
struct GridCell {
    std::int64_t x, y, z;
    bool operator==(const GridCell&) const = default;
};

struct GridCellHash {
    std::size_t operator()(const GridCell& c) const {
        std::uint64_t h = std::uint64_t(c.x) * 0x9e3779b97f4a7c15ull;
        h ^= std::uint64_t(c.y) * 0xc2b2ae3d27d4eb4full + (h << 6) + (h >> 2);
        h ^= std::uint64_t(c.z) * 0x165667b19e3779f9ull + (h << 6) + (h >> 2);
        return std::size_t(h);
    }
};

GridCell cellOf(const Imath::V3f& p, float cellSize) {
    return {std::int64_t(std::floor(p.x / cellSize)), std::int64_t(std::floor(p.y / cellSize)),
            std::int64_t(std::floor(p.z / cellSize))};
}

}  // namespace

VertexWelding weldIdenticalPositions(std::span<const Imath::V3f> positions) {
    std::vector<std::int32_t> order(positions.size());
    std::iota(order.begin(), order.end(), 0);
    // Ties broken by index, so each group's first entry is its lowest index.
    std::sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) {
        if (lexicographicLess(positions[a], positions[b])) return true;
        if (lexicographicLess(positions[b], positions[a])) return false;
        return a < b;
    });
    VertexWelding result;
    result.representative.resize(positions.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        bool sameAsPrevious = i > 0 && positions[order[i]] == positions[order[i - 1]];
        result.representative[order[i]] = sameAsPrevious ? result.representative[order[i - 1]] : order[i];
        if (sameAsPrevious) ++result.welded;
    }
    return result;
}

VertexWelding weldNearbyPositions(std::span<const Imath::V3f> positions, float tolerance) {
    VertexWelding result;
    result.representative.resize(positions.size());
    std::iota(result.representative.begin(), result.representative.end(), 0);
    if (!(tolerance > 0.0f)) return result;
    std::unordered_map<GridCell, std::vector<std::int32_t>, GridCellHash> grid;
    float tolerance2 = tolerance * tolerance;
    for (std::size_t i = 0; i < positions.size(); ++i) {
        GridCell home = cellOf(positions[i], tolerance);
        std::int32_t best = -1;
        for (std::int64_t dz = -1; dz <= 1; ++dz)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                for (std::int64_t dx = -1; dx <= 1; ++dx) {
                    auto it = grid.find({home.x + dx, home.y + dy, home.z + dz});
                    if (it == grid.end()) continue;
                    for (std::int32_t r : it->second) {
                        if ((positions[r] - positions[i]).length2() <= tolerance2 && (best < 0 || r < best)) best = r;
                    }
                }
        if (best >= 0) {
            result.representative[i] = best;
            ++result.welded;
        } else {
            grid[home].push_back(std::int32_t(i));
        }
    }
    return result;
}

}  // namespace opal
