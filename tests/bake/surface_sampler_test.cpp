#include "bake/surface_sampler.h"

#include "bake/random.h"
#include "bake/sample_elimination.h"
#include "bake/subdivision.h"
#include "schema/error.h"
#include "tests/bake/test_meshes.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace opal {
namespace {

double areaSum(const SurfaceSampling& sampling) {
    double sum = 0.0;
    for (const SurfaceSample& s : sampling.samples) sum += s.area;
    return sum;
}

// Brute force: the smallest distance between two samples.
float minimumPairDistance(const SurfaceSampling& sampling) {
    float best = INFINITY;
    const auto& s = sampling.samples;
    for (std::size_t i = 0; i < s.size(); ++i) {
        for (std::size_t j = i + 1; j < s.size(); ++j) best = std::min(best, (s[i].position - s[j].position).length2());
    }
    return std::sqrt(best);
}

TEST(SurfaceSampler, TorusAreasSumToTheClosedFormArea) {
    // A fine torus: its polyhedral area is within 0.1% of 4 pi^2 R r.
    const float R = 2.0f, r = 0.5f;
    RenderMesh mesh = test::torusRenderMesh(R, r, 128, 64);
    SurfaceSampling sampling = sampleSurface(mesh, 4096);
    ASSERT_EQ(sampling.samples.size(), 4096u);
    double exact = 4.0 * std::numbers::pi * std::numbers::pi * R * r;
    EXPECT_NEAR(areaSum(sampling), exact, 0.01 * exact);
    EXPECT_NEAR(sampling.surfaceArea, test::renderMeshArea(mesh), 1e-9 * exact);
    for (const SurfaceSample& s : sampling.samples) {
        EXPECT_NEAR(s.normal.length(), 1.0f, 1e-5f);
        EXPECT_GT(s.normal.dot(test::torusNormal(s.position, R)), 0.99f);
        EXPECT_FLOAT_EQ(s.area, float(sampling.surfaceArea / 4096.0));
    }
}

TEST(SurfaceSampler, SubdividedCubeAreasMatchAFinelyRefinedLimitSurface) {
    RenderMesh mesh = subdivide(test::cube(), {SubdivisionScheme::CatmullClark, 4});
    double limitArea = test::renderMeshArea(subdivide(test::cube(), {SubdivisionScheme::CatmullClark, 7}));
    SurfaceSampling sampling = sampleSurface(mesh, 1024);
    EXPECT_NEAR(areaSum(sampling), limitArea, 0.01 * limitArea);
    for (const SurfaceSample& s : sampling.samples) {
        EXPECT_NEAR(s.normal.length(), 1.0f, 1e-5f);
        EXPECT_GT(s.normal.dot(s.position.normalized()), 0.3f);  // outward on the convex blob
    }
}

TEST(SurfaceSampler, SamplesAreWellSpread) {
    // Poisson-disk radius r_max = sqrt(A / (2 sqrt(3) N)): N disks of that radius in
    // hexagonal packing cover the area, so no two samples can all be 2 r_max apart.
    // Sample elimination reaches more than half of that (about 0.64 here); uniform random
    // points of the same count come within about 1% of it.
    RenderMesh mesh = test::sphereRenderMesh(4);
    SurfaceSampling sampling = sampleSurface(mesh, 2048);
    double rMax = poissonDiskRadius(sampling.surfaceArea, 2048);
    EXPECT_GT(minimumPairDistance(sampling), 0.5 * 2.0 * rMax);

    // No holes: every point of a dense independent random set is near a sample.
    Random random(99, 0);
    float worstGap = 0.0f;
    for (int i = 0; i < 20000; ++i) {
        Imath::V3f p(float(random.uniformDouble() * 2 - 1), float(random.uniformDouble() * 2 - 1),
                     float(random.uniformDouble() * 2 - 1));
        if (p.length2() < 1e-6f) continue;
        p.normalize();
        float nearest = INFINITY;
        for (const SurfaceSample& s : sampling.samples) nearest = std::min(nearest, (s.position - p).length2());
        worstGap = std::max(worstGap, std::sqrt(nearest));
    }
    EXPECT_LT(worstGap, 2.0 * rMax);
}

TEST(SurfaceSampler, DensityIsUniformByArea) {
    // A sphere's octants have equal areas: each should hold an eighth of the samples, far
    // closer than the binomial spread sqrt(N/8) of independent random points allows.
    SurfaceSampling sampling = sampleSurface(test::sphereRenderMesh(4), 4096);
    int octants[8] = {};
    for (const SurfaceSample& s : sampling.samples) {
        ++octants[(s.position.x > 0) + 2 * (s.position.y > 0) + 4 * (s.position.z > 0)];
    }
    for (int count : octants) EXPECT_NEAR(count, 512, 20);

    // A thin torus: the outer half (farther from the axis) has more area than the inner half,
    // in the closed-form ratio (pi R + 2 r) / (pi R - 2 r).
    const float R = 1.0f, r = 0.4f;
    SurfaceSampling torus = sampleSurface(test::torusRenderMesh(R, r, 128, 64), 4096);
    double outer = 0;
    for (const SurfaceSample& s : torus.samples) outer += std::hypot(s.position.x, s.position.y) > R;
    double expected = 4096 * (std::numbers::pi * R + 2 * r) / (2 * std::numbers::pi * R);
    EXPECT_NEAR(outer, expected, 0.015 * 4096);
}

TEST(SurfaceSampler, OriginsReproduceSamplePositions) {
    RenderMesh mesh = subdivide(test::cube(), {SubdivisionScheme::CatmullClark, 2});
    SurfaceSampling sampling = sampleSurface(mesh, 256);
    ASSERT_EQ(sampling.origins.size(), sampling.samples.size());
    for (std::size_t i = 0; i < sampling.samples.size(); ++i) {
        const SampleOrigin& o = sampling.origins[i];
        EXPECT_NEAR(o.barycentric.x + o.barycentric.y + o.barycentric.z, 1.0f, 1e-6f);
        Imath::V3f p = o.barycentric.x * mesh.points[o.vertices[0]] + o.barycentric.y * mesh.points[o.vertices[1]] +
                       o.barycentric.z * mesh.points[o.vertices[2]];
        EXPECT_LT((p - sampling.samples[i].position).length(), 1e-6f);
        // The vertices belong to the named face.
        auto first = mesh.faceVertexIndices.begin() + 4 * o.face;
        for (std::uint32_t v : o.vertices) EXPECT_NE(std::find(first, first + 4, std::int32_t(v)), first + 4);
    }
}

TEST(SurfaceSampler, DeterministicForASeedWhateverTheThreadCount) {
    RenderMesh mesh = test::torusRenderMesh(1.0f, 0.3f, 48, 24);
    SurfaceSampling a = sampleSurface(mesh, 1024, {.seed = 5});
    SurfaceSampling b;
    tbb::task_arena oneThread(1);
    oneThread.execute([&] { b = sampleSurface(mesh, 1024, {.seed = 5}); });
    ASSERT_EQ(a.samples.size(), b.samples.size());
    for (std::size_t i = 0; i < a.samples.size(); ++i) {
        EXPECT_EQ(a.samples[i].position, b.samples[i].position);
        EXPECT_EQ(a.samples[i].normal, b.samples[i].normal);
        EXPECT_EQ(a.origins[i].face, b.origins[i].face);
    }
    SurfaceSampling c = sampleSurface(mesh, 1024, {.seed = 6});
    EXPECT_NE(a.samples[0].position, c.samples[0].position);
}

TEST(SurfaceSampler, ReorderAppliesAPermutation) {
    SurfaceSampling sampling = sampleSurface(test::sphereRenderMesh(2), 64);
    SurfaceSampling original = sampling;
    std::vector<std::uint32_t> order(64);
    for (std::uint32_t i = 0; i < 64; ++i) order[i] = 63 - i;
    reorderSamples(sampling, order);
    for (std::uint32_t i = 0; i < 64; ++i) {
        EXPECT_EQ(sampling.samples[i].position, original.samples[63 - i].position);
        EXPECT_EQ(sampling.origins[i].face, original.origins[63 - i].face);
    }
    order[1] = order[0];
    EXPECT_THROW(reorderSamples(sampling, order), Error);
}

TEST(SurfaceSampler, RefusesBadInput) {
    RenderMesh mesh = test::sphereRenderMesh(1);
    EXPECT_THROW(sampleSurface(mesh, 0), Error);
    RenderMesh noNormals = mesh;
    noNormals.normals.clear();
    EXPECT_THROW(sampleSurface(noNormals, 16), Error);
    RenderMesh flat = mesh;
    for (Imath::V3f& p : flat.points) p = Imath::V3f(0.0f);
    EXPECT_THROW(sampleSurface(flat, 16), Error);
}

}  // namespace
}  // namespace opal
