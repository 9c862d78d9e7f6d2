#include "bake/surface_sampler.h"

#include "bake/mesh_triangles.h"
#include "bake/random.h"
#include "bake/sample_elimination.h"
#include "schema/error.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace opal {
namespace {

struct Candidates {
    std::vector<Imath::V3f> positions, normals;
    std::vector<SampleOrigin> origins;
};

std::vector<double> cumulativeAreas(const MeshTriangles& triangles) {
    std::vector<double> cumulative(triangles.areas.size() + 1, 0.0);
    for (std::size_t t = 0; t < triangles.areas.size(); ++t) cumulative[t + 1] = cumulative[t] + triangles.areas[t];
    return cumulative;
}

// Uniform barycentrics on a triangle (the square-root warp of two uniform numbers).
Imath::V3f uniformBarycentric(Random& random) {
    float s = std::sqrt(random.uniformFloat());
    float r = random.uniformFloat();
    return {1.0f - s, s * (1.0f - r), s * r};
}

// Candidate j is drawn from its own random stream: the set is the same however TBB splits
// the loop.
Candidates drawCandidates(const RenderMesh& mesh, const MeshTriangles& triangles, std::size_t count,
                          std::uint64_t seed) {
    std::vector<double> cumulative = cumulativeAreas(triangles);
    Candidates c;
    c.positions.resize(count);
    c.normals.resize(count);
    c.origins.resize(count);
    tbb::parallel_for(std::size_t(0), count, [&](std::size_t j) {
        Random random(seed, j);
        double quantile = (double(j) + random.uniformDouble()) / double(count) * cumulative.back();
        std::size_t t = std::size_t(std::upper_bound(cumulative.begin(), cumulative.end(), quantile) -
                                    cumulative.begin());
        t = std::clamp<std::size_t>(t, 1, triangles.triangles.size()) - 1;
        const MeshTriangle& triangle = triangles.triangles[t];
        Imath::V3f b = uniformBarycentric(random);
        const auto& v = triangle.vertices;
        c.positions[j] = b.x * mesh.points[v[0]] + b.y * mesh.points[v[1]] + b.z * mesh.points[v[2]];
        Imath::V3f n = b.x * mesh.normals[v[0]] + b.y * mesh.normals[v[1]] + b.z * mesh.normals[v[2]];
        if (!(n.length2() > 0.0f)) n = (mesh.points[v[1]] - mesh.points[v[0]]).cross(mesh.points[v[2]] - mesh.points[v[0]]);
        c.normals[j] = n.normalized();
        c.origins[j] = {triangle.face, v, b};
    });
    return c;
}

void checkInputs(const RenderMesh& mesh, std::size_t count, const MeshTriangles& triangles,
                 const SamplingOptions& options) {
    if (count == 0) throw Error("surface sampling: the sample count must be positive");
    if (mesh.normals.size() != mesh.points.size()) {
        throw Error("surface sampling: the render mesh has " + std::to_string(mesh.normals.size()) + " normals for " +
                    std::to_string(mesh.points.size()) + " points");
    }
    if (!(triangles.totalArea > 0.0) || !std::isfinite(triangles.totalArea)) {
        throw Error("surface sampling: the render mesh has no surface area");
    }
    if (options.candidatesPerSample < 1) throw Error("surface sampling: candidatesPerSample must be at least 1");
    if (double(count) * options.candidatesPerSample >= 4294967296.0) {
        throw Error("surface sampling: " + std::to_string(count) + " x " + std::to_string(options.candidatesPerSample) +
                    " candidates exceed 32-bit indices");
    }
}

}  // namespace

SurfaceSampling sampleSurface(const RenderMesh& mesh, std::size_t count, const SamplingOptions& options) {
    MeshTriangles triangles = triangulate(mesh);
    checkInputs(mesh, count, triangles, options);
    Candidates candidates = drawCandidates(mesh, triangles, count * options.candidatesPerSample, options.seed);
    std::vector<std::uint32_t> kept =
        eliminateSamples(candidates.positions, candidates.normals, count, triangles.totalArea);

    SurfaceSampling result;
    result.surfaceArea = triangles.totalArea;
    float area = float(triangles.totalArea / double(count));
    result.samples.reserve(count);
    result.origins.reserve(count);
    for (std::uint32_t k : kept) {
        result.samples.push_back({candidates.positions[k], candidates.normals[k], area});
        result.origins.push_back(candidates.origins[k]);
    }
    return result;
}

void reorderSamples(SurfaceSampling& sampling, std::span<const std::uint32_t> order) {
    std::size_t n = sampling.samples.size();
    std::vector<char> seen(n, 0);
    for (std::uint32_t i : order) {
        if (i >= n || seen[i]) throw Error("reorderSamples: the order is not a permutation of the samples");
        seen[i] = 1;
    }
    if (order.size() != n) throw Error("reorderSamples: the order is not a permutation of the samples");
    SurfaceSampling result;
    result.surfaceArea = sampling.surfaceArea;
    result.samples.reserve(n);
    result.origins.reserve(n);
    for (std::uint32_t i : order) {
        result.samples.push_back(sampling.samples[i]);
        result.origins.push_back(sampling.origins[i]);
    }
    sampling = std::move(result);
}

}  // namespace opal
