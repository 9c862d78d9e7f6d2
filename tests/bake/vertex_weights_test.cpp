#include "bake/vertex_weights.h"

#include "bake/subdivision.h"
#include "bake/surface_sampler.h"
#include "schema/error.h"
#include "tests/bake/test_meshes.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>

namespace opal {
namespace {

void expectWellFormed(const VertexWeights& weights, std::size_t vertices, std::size_t samples) {
    ASSERT_EQ(weights.offsets.size(), vertices + 1);
    EXPECT_EQ(weights.offsets.front(), 0u);
    EXPECT_EQ(weights.offsets.back(), weights.samples.size());
    EXPECT_EQ(weights.samples.size(), weights.weights.size());
    for (std::size_t v = 0; v < vertices; ++v) {
        ASSERT_LT(weights.offsets[v], weights.offsets[v + 1]) << "vertex " << v << " has no samples";
        double sum = 0.0;
        for (std::uint32_t k = weights.offsets[v]; k < weights.offsets[v + 1]; ++k) {
            EXPECT_LT(weights.samples[k], samples);
            EXPECT_GT(weights.weights[k], 0.0f);
            sum += weights.weights[k];
        }
        EXPECT_NEAR(sum, 1.0, 1e-6) << "vertex " << v;
    }
}

TEST(VertexWeights, SumToOneAndInterpolateLinearFunctions) {
    RenderMesh mesh = subdivide(test::torus(1.0f, 0.4f, 16, 8), {SubdivisionScheme::CatmullClark, 2});
    SurfaceSampling sampling = sampleSurface(mesh, 4096);
    VertexWeights weights = computeVertexWeights(mesh, sampling.samples);
    expectWellFormed(weights, mesh.points.size(), sampling.samples.size());

    // f(x) = a . x + b, interpolated from the samples: the error is |a| times the distance
    // from the vertex to the weighted centroid of its samples, a fraction of the spacing.
    const Imath::V3f a(0.3f, -0.5f, 0.8f);
    const float b = 2.0f;
    double spacing = std::sqrt(sampling.surfaceArea / 4096.0), worst = 0.0, total = 0.0;
    for (std::size_t v = 0; v < mesh.points.size(); ++v) {
        double interpolated = 0.0;
        for (std::uint32_t k = weights.offsets[v]; k < weights.offsets[v + 1]; ++k) {
            interpolated += weights.weights[k] * (a.dot(sampling.samples[weights.samples[k]].position) + b);
        }
        double error = std::abs(interpolated - (a.dot(mesh.points[v]) + b)) / (a.length() * spacing);
        worst = std::max(worst, error);
        total += error;
    }
    EXPECT_LT(total / double(mesh.points.size()), 0.15);
    EXPECT_LT(worst, 0.6);
}

TEST(VertexWeights, DoNotBleedThroughThinParts) {
    // Two parallel squares 0.01 apart, facing away from each other: every vertex uses only
    // samples of its own side, although the other side is nearer than the sample spacing.
    ControlMesh top = test::planeGrid(8);
    ControlMesh both = top;
    for (Imath::V3f p : top.positions) both.positions.push_back(p - Imath::V3f(0, 0, 0.01f));
    std::int32_t offset = std::int32_t(top.positions.size());
    for (std::size_t f = 0; f < top.faceCount(); ++f) {
        const std::int32_t* c = &top.faceVertexIndices[4 * f];
        test::addFace(both, {c[0] + offset, c[3] + offset, c[2] + offset, c[1] + offset});
    }
    RenderMesh mesh = test::asRenderMesh(both, [&](const Imath::V3f& p) {
        return Imath::V3f(0, 0, p.z > -0.005f ? 1.0f : -1.0f);
    });
    SurfaceSampling sampling = sampleSurface(mesh, 1024);
    VertexWeights weights = computeVertexWeights(mesh, sampling.samples);
    expectWellFormed(weights, mesh.points.size(), sampling.samples.size());
    for (std::size_t v = 0; v < mesh.points.size(); ++v) {
        for (std::uint32_t k = weights.offsets[v]; k < weights.offsets[v + 1]; ++k) {
            EXPECT_GT(mesh.normals[v].dot(sampling.samples[weights.samples[k]].normal), 0.5f) << "vertex " << v;
        }
    }
}

TEST(VertexWeights, DeterministicWhateverTheThreadCount) {
    RenderMesh mesh = test::sphereRenderMesh(3);
    SurfaceSampling sampling = sampleSurface(mesh, 1024);
    VertexWeights a = computeVertexWeights(mesh, sampling.samples), b;
    tbb::task_arena oneThread(1);
    oneThread.execute([&] { b = computeVertexWeights(mesh, sampling.samples); });
    EXPECT_EQ(a.offsets, b.offsets);
    EXPECT_EQ(a.samples, b.samples);
    EXPECT_EQ(a.weights, b.weights);
}

TEST(VertexWeights, RefusesBadInput) {
    RenderMesh mesh = test::sphereRenderMesh(1);
    std::vector<SurfaceSample> none;
    EXPECT_THROW(computeVertexWeights(mesh, none), Error);
    std::vector<SurfaceSample> zeroArea(4);
    EXPECT_THROW(computeVertexWeights(mesh, zeroArea), Error);
}

}  // namespace
}  // namespace opal
