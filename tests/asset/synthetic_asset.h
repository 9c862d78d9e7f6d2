// A small, seeded, self-consistent TranslucentAsset for sidecar tests: 2 charts of 4 x 4
// samples, K = 3 sparse transfer matrices, vertex weights for a 12-vertex mesh and a
// 2-term environment transfer over a 6 x 2 x 2 cube map.
#pragma once

#include "schema/asset/translucent_asset.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace opal::test {

inline std::vector<std::uint32_t> sortedSubset(std::mt19937& rng, std::uint32_t bound, double density) {
    std::vector<std::uint32_t> picked;
    std::bernoulli_distribution take(density);
    for (std::uint32_t i = 0; i < bound; ++i)
        if (take(rng)) picked.push_back(i);
    return picked;
}

// CSR with ascending indices per row; offsets of type Offset.
template <class Offset>
void randomCsr(std::mt19937& rng, std::size_t rows, std::uint32_t bound, double density,
               std::vector<Offset>& offsets, std::vector<std::uint32_t>& indices, std::vector<float>& values) {
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    offsets.assign(1, 0);
    for (std::size_t r = 0; r < rows; ++r) {
        for (std::uint32_t i : sortedSubset(rng, bound, density)) {
            indices.push_back(i);
            values.push_back(gauss(rng));
        }
        offsets.push_back(static_cast<Offset>(indices.size()));
    }
}

inline RenderMesh gridMesh() {
    RenderMesh mesh;  // 4 x 3 vertices, 3 x 2 quads in the z = 0 plane
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x) {
            mesh.points.push_back({float(x), float(y), 0.0f});
            mesh.normals.push_back({0.0f, 0.0f, 1.0f});
        }
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x) {
            mesh.faceVertexCounts.push_back(4);
            for (int v : {y * 4 + x, y * 4 + x + 1, (y + 1) * 4 + x + 1, (y + 1) * 4 + x}) mesh.faceVertexIndices.push_back(v);
        }
    return mesh;
}

inline VertexWeights randomWeights(std::mt19937& rng, std::size_t vertices, std::uint32_t samples) {
    VertexWeights w;
    w.offsets.push_back(0);
    std::uniform_int_distribution<std::uint32_t> count(1, 4), sample(0, samples - 1);
    std::uniform_real_distribution<float> weight(0.1f, 1.0f);
    for (std::size_t v = 0; v < vertices; ++v) {
        std::uint32_t n = count(rng);
        std::vector<float> raw(n);
        float sum = 0.0f;
        for (float& x : raw) sum += x = weight(rng);
        for (float x : raw) {
            w.samples.push_back(sample(rng));
            w.weights.push_back(x / sum);
        }
        w.offsets.push_back(static_cast<std::uint32_t>(w.samples.size()));
    }
    return w;
}

inline std::vector<SurfaceSample> randomSamples(std::mt19937& rng, std::size_t n) {
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    std::uniform_real_distribution<float> area(0.01f, 0.2f);
    std::vector<SurfaceSample> samples(n);
    for (SurfaceSample& s : samples) {
        s.position = {gauss(rng), gauss(rng), gauss(rng)};
        s.normal = Imath::V3f(gauss(rng), gauss(rng), gauss(rng) + 0.1f).normalized();
        s.area = area(rng);
    }
    return samples;
}

inline TranslucentAsset syntheticAsset(std::uint32_t seed = 1) {
    std::mt19937 rng(seed);
    TranslucentAsset a;
    a.name = "syntheticCube";
    a.unitsPerMm = 0.1;
    a.mesh = gridMesh();
    a.layout = {2, 2};
    auto n = static_cast<std::uint32_t>(a.layout.cells());
    a.samples = randomSamples(rng, n);
    a.vertexWeights = randomWeights(rng, a.mesh.points.size(), n);
    a.transfer.keepFraction = 0.25;
    a.transfer.energyFraction = 0.97;
    a.transfer.valueSteps = {0.0, 1e-3, 0.02};  // matrix 0 stored exactly, 1 and 2 on grids
    for (int k = 0; k < 3; ++k) {
        SparseMatrix m;
        m.rows = m.cols = n;
        randomCsr(rng, n, n, 0.1, m.rowOffsets, m.columns, m.values);
        a.transfer.perBasis.push_back(std::move(m));
    }
    a.environment.cubeFaceSize = 2;
    a.environment.fresnelTerms = 2;
    randomCsr(rng, n * 2, 6 * 2 * 2, 0.15, a.environment.offsets, a.environment.indices, a.environment.values);
    return a;
}

}  // namespace opal::test
