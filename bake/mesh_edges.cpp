#include "bake/mesh_edges.h"

#include <algorithm>
#include <tuple>

namespace opal {
namespace {

struct CornerEdge {
    std::int32_t low, high, face, corner;
    bool forward;
};

std::vector<CornerEdge> cornerEdges(std::span<const std::int32_t> counts, std::span<const std::int32_t> indices) {
    std::vector<CornerEdge> records;
    records.reserve(indices.size());
    std::int32_t start = 0;
    for (std::size_t f = 0; f < counts.size(); ++f) {
        std::int32_t n = counts[f];
        for (std::int32_t c = 0; c < n; ++c) {
            std::int32_t a = indices[start + c];
            std::int32_t b = indices[start + (c + 1) % n];
            records.push_back({std::min(a, b), std::max(a, b), std::int32_t(f), start + c, a < b});
        }
        start += n;
    }
    std::sort(records.begin(), records.end(), [](const CornerEdge& x, const CornerEdge& y) {
        return std::tie(x.low, x.high, x.face, x.corner) < std::tie(y.low, y.high, y.face, y.corner);
    });
    return records;
}

}  // namespace

MeshEdges::MeshEdges(std::span<const std::int32_t> faceVertexCounts, std::span<const std::int32_t> faceVertexIndices) {
    std::vector<CornerEdge> records = cornerEdges(faceVertexCounts, faceVertexIndices);
    uses_.reserve(records.size());
    cornerEdge_.resize(faceVertexIndices.size());
    for (const CornerEdge& r : records) {
        bool sameEdge = !edges_.empty() && edges_.back().low == r.low && edges_.back().high == r.high;
        if (!sameEdge) edges_.push_back({r.low, r.high, std::uint32_t(uses_.size()), 0});
        ++edges_.back().useCount;
        uses_.push_back({r.face, r.corner, r.forward});
        cornerEdge_[r.corner] = std::int32_t(edges_.size() - 1);
    }
}

}  // namespace opal
