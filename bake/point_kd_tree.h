// A k-d tree over a fixed set of 3D points, for the neighbour queries of sample
// elimination and vertex weights. Median splits on the widest axis, small leaves; the
// shape depends only on the points, and every query returns its result in a
// deterministic order, so callers running queries in parallel get identical output.
#pragma once

#include <Imath/ImathVec.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace opal {

class PointKdTree {
public:
    struct Neighbour {
        std::uint32_t index;
        float distance2;  // squared Euclidean distance to the query
    };

    explicit PointKdTree(std::span<const Imath::V3f> points);

    std::size_t size() const { return points_.size(); }

    // Every point within `radius` of `query` (inclusive), in increasing index order.
    void findWithinRadius(const Imath::V3f& query, float radius, std::vector<std::uint32_t>& out) const;

    // The k nearest points (fewer if the tree is smaller), nearest first; equal distances
    // in increasing index order.
    void findNearest(const Imath::V3f& query, std::size_t k, std::vector<Neighbour>& out) const;

private:
    struct Node {
        std::uint32_t begin, end;  // range in points_/indices_
        std::uint32_t right;       // index of the right child (left child is this + 1); 0 for a leaf
        std::uint8_t axis;
        float split;  // left holds coordinates <= split, right >= split
    };

    void build(std::span<const Imath::V3f> points, std::uint32_t node, std::uint32_t begin, std::uint32_t end);
    void radiusSearch(std::uint32_t node, const Imath::V3f& query, float radius2, float radius,
                      std::vector<std::uint32_t>& out) const;
    template <class Heap>
    void nearestSearch(std::uint32_t node, const Imath::V3f& query, std::size_t k, Heap& heap) const;

    std::vector<Imath::V3f> points_;     // in tree order
    std::vector<std::uint32_t> indices_;  // tree order -> caller's index
    std::vector<Node> nodes_;             // pre-order
};

}  // namespace opal
