#include "bake/sample_elimination.h"

#include "bake/point_kd_tree.h"
#include "schema/error.h"

#include <Imath/ImathBox.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace opal {
namespace {

// Yuksel's parameters: the weight falls off as (1 - d / 2 r_max)^alpha with alpha = 8;
// weight limiting (gamma, beta) stops candidates closer than r_min from dominating when
// there are many more candidates than samples.
constexpr double kGamma = 1.5;
constexpr double kBeta = 0.65;
constexpr float kMinNormalAgreement = -0.5f;  // cos(120 degrees)
constexpr std::size_t kBlock = 4096;          // candidates per parallel task

struct EliminationRadii {
    double dMax;  // 2 r_max: the reach of a candidate's weight
    double rMin;  // distances below this count as rMin
};

// The crowding one candidate puts on another at distance d.
double pairWeight(double d, const EliminationRadii& radii) {
    double limited = std::clamp(d, radii.rMin, radii.dMax);
    double t = 1.0 - limited / radii.dMax, t2 = t * t, t4 = t2 * t2;
    return t4 * t4;  // alpha = 8, without std::pow in the hot loop
}

// Neighbours within dMax that face the same way, per candidate (CSR). Built in fixed
// blocks and concatenated in block order, so the result does not depend on scheduling.
struct NeighbourLists {
    std::vector<std::uint64_t> offsets;
    std::vector<std::uint32_t> indices;
};

NeighbourLists findNeighbours(std::span<const Imath::V3f> positions, std::span<const Imath::V3f> normals,
                              const PointKdTree& tree, float reach) {
    std::size_t n = positions.size();
    std::size_t blocks = (n + kBlock - 1) / kBlock;
    std::vector<std::vector<std::uint32_t>> blockIndices(blocks), blockCounts(blocks);
    tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t b) {
        std::vector<std::uint32_t> found;
        for (std::size_t i = b * kBlock; i < std::min(n, (b + 1) * kBlock); ++i) {
            tree.findWithinRadius(positions[i], reach, found);
            std::uint32_t count = 0;
            for (std::uint32_t j : found) {
                if (j == i || normals[i].dot(normals[j]) < kMinNormalAgreement) continue;
                blockIndices[b].push_back(j);
                ++count;
            }
            blockCounts[b].push_back(count);
        }
    });
    NeighbourLists lists;
    lists.offsets.reserve(n + 1);
    lists.offsets.push_back(0);
    for (std::size_t b = 0; b < blocks; ++b) {
        for (std::uint32_t count : blockCounts[b]) lists.offsets.push_back(lists.offsets.back() + count);
        lists.indices.insert(lists.indices.end(), blockIndices[b].begin(), blockIndices[b].end());
    }
    return lists;
}

// Each candidate's total crowding: the sum of its neighbours' weights, in neighbour order.
template <class WeightBetween>
std::vector<double> crowding(const NeighbourLists& neighbours, WeightBetween weightBetween) {
    std::vector<double> weights(neighbours.offsets.size() - 1, 0.0);
    tbb::parallel_for(std::size_t(0), weights.size(), [&](std::size_t i) {
        for (std::uint64_t k = neighbours.offsets[i]; k < neighbours.offsets[i + 1]; ++k) {
            weights[i] += weightBetween(std::uint32_t(i), neighbours.indices[k]);
        }
    });
    return weights;
}

// A binary max-heap of candidates keyed by (weight, index), with each candidate's
// position in the heap so its weight can be lowered in place.
class CrowdingHeap {
public:
    explicit CrowdingHeap(std::vector<double> weights) : weight_(std::move(weights)) {
        heap_.resize(weight_.size());
        std::iota(heap_.begin(), heap_.end(), 0u);
        slot_.resize(weight_.size());
        for (std::size_t i = 0; i < heap_.size(); ++i) slot_[heap_[i]] = std::uint32_t(i);
        for (std::size_t i = heap_.size() / 2; i-- > 0;) siftDown(i);
    }

    std::size_t size() const { return heap_.size(); }
    bool contains(std::uint32_t c) const { return slot_[c] != kRemoved; }

    std::uint32_t popMostCrowded() {
        std::uint32_t top = heap_[0];
        place(heap_.back(), 0);
        heap_.pop_back();
        slot_[top] = kRemoved;
        if (!heap_.empty()) siftDown(0);
        return top;
    }

    void lower(std::uint32_t c, double amount) {
        weight_[c] -= amount;
        siftDown(slot_[c]);
    }

private:
    static constexpr std::uint32_t kRemoved = ~0u;

    bool above(std::uint32_t a, std::uint32_t b) const {
        return weight_[a] > weight_[b] || (weight_[a] == weight_[b] && a > b);
    }
    void place(std::uint32_t c, std::size_t i) {
        heap_[i] = c;
        slot_[c] = std::uint32_t(i);
    }
    void siftDown(std::size_t i) {
        std::uint32_t c = heap_[i];
        for (;;) {
            std::size_t child = 2 * i + 1;
            if (child >= heap_.size()) break;
            if (child + 1 < heap_.size() && above(heap_[child + 1], heap_[child])) ++child;
            if (!above(heap_[child], c)) break;
            place(heap_[child], i);
            i = child;
        }
        place(c, i);
    }

    std::vector<double> weight_;
    std::vector<std::uint32_t> heap_;
    std::vector<std::uint32_t> slot_;
};

// Candidates in Morton (Z-curve) order of their positions: neighbours then sit close in
// memory, which keeps the elimination loop's random accesses in cache.
std::vector<std::uint32_t> spatialOrder(std::span<const Imath::V3f> positions) {
    Imath::Box3f box;
    for (const Imath::V3f& p : positions) box.extendBy(p);
    Imath::V3f scale = box.size();
    for (int a = 0; a < 3; ++a) scale[a] = scale[a] > 0.0f ? 1023.0f / scale[a] : 0.0f;
    auto spread = [](std::uint64_t x) {  // 10 bits -> every third bit of 30
        x = (x | (x << 16)) & 0x030000FFull;
        x = (x | (x << 8)) & 0x0300F00Full;
        x = (x | (x << 4)) & 0x030C30C3ull;
        return (x | (x << 2)) & 0x09249249ull;
    };
    std::vector<std::uint64_t> keys(positions.size());
    tbb::parallel_for(std::size_t(0), positions.size(), [&](std::size_t i) {
        Imath::V3f q = (positions[i] - box.min) * scale;
        std::uint64_t code = spread(std::uint64_t(q.x)) | spread(std::uint64_t(q.y)) << 1 | spread(std::uint64_t(q.z)) << 2;
        keys[i] = code << 32 | i;  // the index breaks ties: a strict, deterministic order
    });
    std::sort(keys.begin(), keys.end());
    std::vector<std::uint32_t> order(positions.size());
    for (std::size_t i = 0; i < keys.size(); ++i) order[i] = std::uint32_t(keys[i] & 0xffffffffu);
    return order;
}

}  // namespace

double poissonDiskRadius(double surfaceArea, std::size_t count) {
    return std::sqrt(surfaceArea / (2.0 * std::sqrt(3.0) * double(count)));
}

std::vector<std::uint32_t> eliminateSamples(std::span<const Imath::V3f> positions,
                                            std::span<const Imath::V3f> normals, std::size_t count,
                                            double surfaceArea) {
    std::size_t candidates = positions.size();
    if (count == 0 || count > candidates || candidates >= (std::size_t(1) << 32) || normals.size() != candidates ||
        !(surfaceArea > 0.0)) {
        throw Error("sample elimination needs 0 < count <= candidates < 2^32 (" + std::to_string(count) + " of " +
                    std::to_string(candidates) + "), a normal per candidate and a positive area");
    }
    double rMax = poissonDiskRadius(surfaceArea, count);
    EliminationRadii radii{2.0 * rMax, rMax * (1.0 - std::pow(double(count) / double(candidates), kGamma)) * kBeta};
    std::vector<std::uint32_t> order = spatialOrder(positions);
    std::vector<Imath::V3f> points(candidates), directions(candidates);
    for (std::size_t i = 0; i < candidates; ++i) {
        points[i] = positions[order[i]];
        directions[i] = normals[order[i]];
    }
    NeighbourLists neighbours = findNeighbours(points, directions, PointKdTree(points), float(radii.dMax));
    auto weightBetween = [&](std::uint32_t i, std::uint32_t j) {
        return pairWeight(double((points[i] - points[j]).length()), radii);
    };
    CrowdingHeap heap(crowding(neighbours, weightBetween));
    while (heap.size() > count) {
        std::uint32_t removed = heap.popMostCrowded();
        for (std::uint64_t k = neighbours.offsets[removed]; k < neighbours.offsets[removed + 1]; ++k) {
            std::uint32_t j = neighbours.indices[k];
            if (heap.contains(j)) heap.lower(j, weightBetween(removed, j));
        }
    }
    std::vector<std::uint32_t> kept;
    kept.reserve(count);
    for (std::uint32_t i = 0; i < candidates; ++i) {
        if (heap.contains(i)) kept.push_back(order[i]);
    }
    std::sort(kept.begin(), kept.end());
    return kept;
}

}  // namespace opal
