#include "bench/jensen_buhler.h"

#include "schema/error.h"
#include "schema/scatter/dipole.h"
#include "schema/scatter/dipole_profile.h"

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

namespace opal::bench {

namespace {

// Rec. 709 luminance: the weight of a sample's position in its node's mean (pbrt-v2 uses y()).
double luminance(const double e[3]) { return 0.2126 * e[0] + 0.7152 * e[1] + 0.0722 * e[2]; }

double distance2(const double a[3], const double b[3]) {
    const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return dx * dx + dy * dy + dz * dz;
}

}  // namespace

JensenBuhlerOctree::JensenBuhlerOctree(const TranslucentAsset& asset) {
    const std::size_t n = asset.samples.size();
    if (n == 0) throw Error("Jensen-Buhler octree: the asset has no samples");
    const double toMm = 1.0 / asset.unitsPerMm;
    points_.resize(n);
    Node root;
    std::fill_n(root.lo, 3, HUGE_VAL);
    std::fill_n(root.hi, 3, -HUGE_VAL);
    for (std::size_t i = 0; i < n; ++i) {
        const SurfaceSample& s = asset.samples[i];
        Point& p = points_[i];
        for (int a = 0; a < 3; ++a) {
            p.position[a] = double(s.position[a]) * toMm;
            root.lo[a] = std::min(root.lo[a], p.position[a]);
            root.hi[a] = std::max(root.hi[a], p.position[a]);
        }
        p.area = double(s.area) * toMm * toMm;
        p.sample = std::uint32_t(i);
    }
    root.end = std::uint32_t(n);
    nodes_.push_back(root);
    split(0, 0);
    slot_.resize(n);
    for (std::size_t k = 0; k < n; ++k) slot_[points_[k].sample] = std::uint32_t(k);
}

// Partitions the node's samples into its non-empty octants (a stable counting sort), appends
// those children contiguously and splits them in turn.
void JensenBuhlerOctree::split(std::uint32_t index, std::uint32_t depth) {
    const Node node = nodes_[index];
    if (node.end - node.begin <= kLeafSamples || depth == kMaxDepth) return;
    double mid[3];
    for (int a = 0; a < 3; ++a) mid[a] = 0.5 * (node.lo[a] + node.hi[a]);
    auto octant = [&](const Point& p) {
        return (p.position[0] >= mid[0] ? 1u : 0u) | (p.position[1] >= mid[1] ? 2u : 0u) |
               (p.position[2] >= mid[2] ? 4u : 0u);
    };
    std::array<std::uint32_t, 9> start{};
    for (std::uint32_t k = node.begin; k < node.end; ++k) ++start[octant(points_[k]) + 1];
    for (int o = 0; o < 8; ++o) start[o + 1] += start[o];
    const std::vector<Point> range(points_.begin() + node.begin, points_.begin() + node.end);
    std::array<std::uint32_t, 8> next{};
    for (int o = 0; o < 8; ++o) next[o] = node.begin + start[o];
    for (const Point& p : range) points_[next[octant(p)]++] = p;

    const auto first = std::uint32_t(nodes_.size());
    for (std::uint32_t o = 0; o < 8; ++o) {
        if (start[o + 1] == start[o]) continue;
        Node child;
        for (int a = 0; a < 3; ++a) {
            const bool upper = (o >> a) & 1u;
            child.lo[a] = upper ? mid[a] : node.lo[a];
            child.hi[a] = upper ? node.hi[a] : mid[a];
        }
        child.begin = node.begin + start[o];
        child.end = node.begin + start[o + 1];
        nodes_.push_back(child);
    }
    const auto last = std::uint32_t(nodes_.size());
    nodes_[index].firstChild = first;
    nodes_[index].children = last - first;
    for (std::uint32_t c = first; c < last; ++c) split(c, depth + 1);
}

void JensenBuhlerOctree::setIrradiance(std::span<const float> irradiance) {
    if (irradiance.size() != 3 * points_.size())
        throw Error("Jensen-Buhler octree: " + std::to_string(irradiance.size()) + " irradiance values for " +
                    std::to_string(points_.size()) + " RGB samples");
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points_.size(), 4096),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t k = r.begin(); k != r.end(); ++k)
                              for (int c = 0; c < 3; ++c)
                                  points_[k].irradiance[c] = double(irradiance[3 * std::size_t(points_[k].sample) + c]);
                      });
    refit(0);
    lit_ = true;
}

// The node's area, area-weighted E and flux-weighted position from its samples or children
// (post-order). A node without flux takes its area-weighted centroid (its aggregate adds 0).
void JensenBuhlerOctree::refit(std::uint32_t index) {
    double area = 0.0, flux[3] = {0, 0, 0}, weight = 0.0, weighted[3] = {0, 0, 0}, centroid[3] = {0, 0, 0};
    auto add = [&](const double position[3], double a, const double e[3]) {
        area += a;
        const double w = a * luminance(e);
        weight += w;
        for (int c = 0; c < 3; ++c) {
            flux[c] += a * e[c];
            weighted[c] += w * position[c];
            centroid[c] += a * position[c];
        }
    };
    const Node& node = nodes_[index];
    if (node.children == 0) {
        for (std::uint32_t k = node.begin; k < node.end; ++k) add(points_[k].position, points_[k].area, points_[k].irradiance);
    } else {
        for (std::uint32_t c = node.firstChild; c < node.firstChild + node.children; ++c) {
            refit(c);
            add(nodes_[c].position, nodes_[c].area, nodes_[c].irradiance);
        }
    }
    Node& out = nodes_[index];
    out.area = area;
    for (int c = 0; c < 3; ++c) {
        out.irradiance[c] = area > 0.0 ? flux[c] / area : 0.0;
        out.position[c] = weight > 0.0 ? weighted[c] / weight : area > 0.0 ? centroid[c] / area : 0.5 * (out.lo[c] + out.hi[c]);
    }
}

bool JensenBuhlerOctree::inside(const Node& node, const double x[3]) const {
    for (int a = 0; a < 3; ++a)
        if (x[a] < node.lo[a] || x[a] > node.hi[a]) return false;
    return true;
}

JensenBuhlerOctree::Result JensenBuhlerOctree::radiance(const Material& material, double maxError,
                                                        std::span<const std::uint32_t> outputs) const {
    if (!lit_) throw Error("Jensen-Buhler octree: no irradiance set");
    if (!(maxError >= 0.0) || !std::isfinite(maxError))
        throw Error("Jensen-Buhler octree: maxError = " + std::to_string(maxError) + " must be finite and >= 0");
    validateMaterial(material, "Jensen-Buhler octree");
    const std::size_t n = points_.size();
    for (std::uint32_t o : outputs)
        if (o >= n) throw Error("Jensen-Buhler octree: output sample " + std::to_string(o) + " out of range");
    const DipoleProfile profile[3] = {DipoleProfile(material.channel(0)), DipoleProfile(material.channel(1)),
                                      DipoleProfile(material.channel(2))};
    const std::size_t count = outputs.empty() ? n : outputs.size();
    Result result;
    result.radiance.resize(3 * count);
    tbb::combinable<std::uint64_t> interactions([] { return std::uint64_t(0); });
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 16), [&](const tbb::blocked_range<std::size_t>& r) {
        std::uint64_t& used = interactions.local();
        // Depth-first: at most 8 children pushed per level below kMaxDepth.
        std::array<std::uint32_t, 8 * (kMaxDepth + 1)> stack;
        for (std::size_t j = r.begin(); j != r.end(); ++j) {
            const std::uint32_t sample = outputs.empty() ? std::uint32_t(j) : outputs[j];
            const Point& self = points_[slot_[sample]];
            double sum[3] = {0.0, 0.0, 0.0};
            auto gather = [&](const double position[3], double area, const double e[3]) {
                const double r2 = distance2(self.position, position);
                for (int c = 0; c < 3; ++c) sum[c] += profile[c](r2) * area * e[c];
                ++used;
            };
            std::size_t top = 0;
            stack[top++] = 0;
            while (top > 0) {
                const Node& node = nodes_[stack[--top]];
                if (node.area < maxError * distance2(self.position, node.position) && !inside(node, self.position)) {
                    gather(node.position, node.area, node.irradiance);
                } else if (node.children == 0) {
                    for (std::uint32_t k = node.begin; k < node.end; ++k)
                        if (points_[k].sample != sample) gather(points_[k].position, points_[k].area, points_[k].irradiance);
                } else {
                    for (std::uint32_t c = node.firstChild; c < node.firstChild + node.children; ++c) stack[top++] = c;
                }
            }
            // The sample's own light over its own disk, as referenceGather.
            const double radius = std::sqrt(self.area / std::numbers::pi);
            for (int c = 0; c < 3; ++c) sum[c] += dipoleDiskReflectance(radius, material.channel(c)) * self.irradiance[c];
            for (int c = 0; c < 3; ++c) result.radiance[3 * j + c] = float(sum[c] / std::numbers::pi);
        }
    });
    result.interactionsPerOutput = double(interactions.combine(std::plus<>())) / double(count);
    return result;
}

}  // namespace opal::bench
