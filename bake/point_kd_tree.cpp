#include "bake/point_kd_tree.h"

#include <Imath/ImathBox.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <numeric>

namespace opal {
namespace {

constexpr std::uint32_t kLeafSize = 8;
constexpr std::uint32_t kParallelBuildSize = 16384;

// The tree's shape depends only on the point count (splits at the middle), so the number
// of nodes of a subtree is known before it is built: subtrees can be built in parallel
// into their own pre-order slots.
std::uint32_t subtreeNodes(std::uint32_t count) {
    if (count <= kLeafSize) return 1;
    std::uint32_t half = count / 2;
    return 1 + subtreeNodes(half) + subtreeNodes(count - half);
}

// Lexicographic on (distance, index): the heap's order, and the result's.
bool closer(const PointKdTree::Neighbour& a, const PointKdTree::Neighbour& b) {
    return a.distance2 < b.distance2 || (a.distance2 == b.distance2 && a.index < b.index);
}

}  // namespace

PointKdTree::PointKdTree(std::span<const Imath::V3f> points) : indices_(points.size()) {
    std::iota(indices_.begin(), indices_.end(), 0u);
    if (points.empty()) return;
    nodes_.resize(subtreeNodes(std::uint32_t(points.size())));
    build(points, 0, 0, std::uint32_t(points.size()));
    points_.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) points_[i] = points[indices_[i]];
}

void PointKdTree::build(std::span<const Imath::V3f> points, std::uint32_t node, std::uint32_t begin,
                        std::uint32_t end) {
    Node& n = nodes_[node];
    n.begin = begin;
    n.end = end;
    n.right = 0;
    if (end - begin <= kLeafSize) return;
    Imath::Box3f bounds;
    for (std::uint32_t i = begin; i < end; ++i) bounds.extendBy(points[indices_[i]]);
    n.axis = std::uint8_t(bounds.majorAxis());
    std::uint32_t mid = begin + (end - begin) / 2;
    int axis = n.axis;
    std::nth_element(indices_.begin() + begin, indices_.begin() + mid, indices_.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) {
                         float ca = points[a][axis], cb = points[b][axis];
                         return ca < cb || (ca == cb && a < b);
                     });
    n.split = points[indices_[mid]][axis];
    std::uint32_t left = node + 1;
    n.right = left + subtreeNodes(mid - begin);
    std::uint32_t right = n.right;
    if (end - begin >= kParallelBuildSize) {
        tbb::parallel_invoke([&] { build(points, left, begin, mid); }, [&] { build(points, right, mid, end); });
    } else {
        build(points, left, begin, mid);
        build(points, right, mid, end);
    }
}

void PointKdTree::findWithinRadius(const Imath::V3f& query, float radius, std::vector<std::uint32_t>& out) const {
    out.clear();
    if (nodes_.empty()) return;
    radiusSearch(0, query, radius * radius, radius, out);
    std::sort(out.begin(), out.end());
}

void PointKdTree::radiusSearch(std::uint32_t node, const Imath::V3f& query, float radius2, float radius,
                               std::vector<std::uint32_t>& out) const {
    const Node& n = nodes_[node];
    if (n.right == 0) {
        for (std::uint32_t i = n.begin; i < n.end; ++i) {
            if ((points_[i] - query).length2() <= radius2) out.push_back(indices_[i]);
        }
        return;
    }
    float d = query[n.axis] - n.split;
    if (d <= radius) radiusSearch(node + 1, query, radius2, radius, out);
    if (d >= -radius) radiusSearch(n.right, query, radius2, radius, out);
}

void PointKdTree::findNearest(const Imath::V3f& query, std::size_t k, std::vector<Neighbour>& out) const {
    out.clear();
    if (nodes_.empty() || k == 0) return;
    nearestSearch(0, query, k, out);  // `out` is a max-heap under `closer` while searching
    std::sort_heap(out.begin(), out.end(), closer);
}

template <class Heap>
void PointKdTree::nearestSearch(std::uint32_t node, const Imath::V3f& query, std::size_t k, Heap& heap) const {
    const Node& n = nodes_[node];
    if (n.right == 0) {
        for (std::uint32_t i = n.begin; i < n.end; ++i) {
            Neighbour candidate{indices_[i], (points_[i] - query).length2()};
            if (heap.size() < k) {
                heap.push_back(candidate);
                std::push_heap(heap.begin(), heap.end(), closer);
            } else if (closer(candidate, heap.front())) {
                std::pop_heap(heap.begin(), heap.end(), closer);
                heap.back() = candidate;
                std::push_heap(heap.begin(), heap.end(), closer);
            }
        }
        return;
    }
    float d = query[n.axis] - n.split;
    std::uint32_t nearSide = d <= 0 ? node + 1 : n.right;
    std::uint32_t farSide = d <= 0 ? n.right : node + 1;
    nearestSearch(nearSide, query, k, heap);
    // <= keeps points at exactly the worst distance reachable, for the index tie-break.
    if (heap.size() < k || d * d <= heap.front().distance2) nearestSearch(farSide, query, k, heap);
}

}  // namespace opal
