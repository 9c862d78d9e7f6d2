#include "bake/vertex_weights.h"

#include "bake/point_kd_tree.h"
#include "schema/error.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace opal {
namespace {

void checkInputs(const RenderMesh& mesh, std::span<const SurfaceSample> samples, const VertexWeightOptions& options) {
    if (mesh.normals.size() != mesh.points.size()) {
        throw Error("vertex weights: the render mesh has " + std::to_string(mesh.normals.size()) + " normals for " +
                    std::to_string(mesh.points.size()) + " points");
    }
    if (samples.empty()) throw Error("vertex weights: there are no samples");
    if (options.neighbours == 0) throw Error("vertex weights: neighbours must be at least 1");
}

double sampleSpacing(std::span<const SurfaceSample> samples) {
    double area = 0.0;
    for (const SurfaceSample& s : samples) area += s.area;
    double spacing = std::sqrt(area / double(samples.size()));
    if (!(spacing > 0.0) || !std::isfinite(spacing)) throw Error("vertex weights: the samples have no area");
    return spacing;
}

// The nearest agreeing samples of one vertex (or its nearest sample), with weights.
std::size_t weighVertex(const Imath::V3f& point, const Imath::V3f& normal, std::span<const SurfaceSample> samples,
                        const PointKdTree& tree, double spacing, const VertexWeightOptions& options,
                        std::uint32_t* indices, float* weights) {
    std::vector<PointKdTree::Neighbour> nearest;
    tree.findNearest(point, std::max(options.searched, options.neighbours), nearest);
    std::size_t count = 0;
    for (const PointKdTree::Neighbour& n : nearest) {
        if (count == options.neighbours) break;
        if (normal.dot(samples[n.index].normal) > options.minNormalAgreement) nearest[count++] = n;
    }
    if (count == 0) count = 1;  // nothing agrees: the nearest sample (nearest[0]) alone
    // Relative to the nearest distance, so far-away samples cannot underflow to zero.
    double d0 = nearest[0].distance2, total = 0.0;
    std::vector<double> w(count);
    for (std::size_t k = 0; k < count; ++k) {
        w[k] = std::exp(-(double(nearest[k].distance2) - d0) / (spacing * spacing));
        total += w[k];
    }
    for (std::size_t k = 0; k < count; ++k) {
        indices[k] = nearest[k].index;
        weights[k] = float(w[k] / total);
    }
    return count;
}

}  // namespace

VertexWeights computeVertexWeights(const RenderMesh& mesh, std::span<const SurfaceSample> samples,
                                   const VertexWeightOptions& options) {
    checkInputs(mesh, samples, options);
    double spacing = sampleSpacing(samples);
    std::vector<Imath::V3f> positions(samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) positions[i] = samples[i].position;
    PointKdTree tree(positions);

    std::size_t vertices = mesh.points.size(), k = options.neighbours;
    std::vector<std::uint32_t> indices(vertices * k);
    std::vector<float> weights(vertices * k);
    std::vector<std::uint32_t> counts(vertices);
    tbb::parallel_for(std::size_t(0), vertices, [&](std::size_t v) {
        counts[v] = std::uint32_t(weighVertex(mesh.points[v], mesh.normals[v], samples, tree, spacing, options,
                                              &indices[v * k], &weights[v * k]));
    });

    VertexWeights result;
    result.offsets.reserve(vertices + 1);
    result.offsets.push_back(0);
    for (std::size_t v = 0; v < vertices; ++v) {
        result.offsets.push_back(result.offsets.back() + counts[v]);
        result.samples.insert(result.samples.end(), indices.begin() + v * k, indices.begin() + v * k + counts[v]);
        result.weights.insert(result.weights.end(), weights.begin() + v * k, weights.begin() + v * k + counts[v]);
    }
    return result;
}

}  // namespace opal
