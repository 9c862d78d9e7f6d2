// VertexGather: the render-mesh vertices' radiance, visited in cache order, against the sum
// written plainly in the vertices' own order; two signals in one pass against two passes.
#include "delegate/relight/vertex_gather.h"
#include "schema/error.h"

#include <gtest/gtest.h>

#include <random>

namespace opal {
namespace {

// `vertices` vertices with 0 to 9 weights each on random samples (vertex 0 has none).
VertexWeights randomWeights(std::uint32_t vertices, std::uint32_t samples, std::uint32_t seed) {
    std::mt19937 rng(seed);
    VertexWeights w;
    w.offsets.push_back(0);
    for (std::uint32_t v = 0; v < vertices; ++v) {
        const std::uint32_t count = v == 0 ? 0 : rng() % 10;
        for (std::uint32_t e = 0; e < count; ++e) {
            w.samples.push_back(rng() % samples);
            w.weights.push_back(float(rng() % 1000) / 1000.0f);
        }
        w.offsets.push_back(std::uint32_t(w.samples.size()));
    }
    return w;
}

// Sample indices are stored in 16 bits up to 65,536 samples and in 32 above: both sides
// of the boundary, with the last sample read.
void expectThePlainSum(std::uint32_t samples) {
    const std::uint32_t vertices = 3000;
    VertexWeights w = randomWeights(vertices, samples, 5);
    w.samples.back() = samples - 1;
    std::mt19937 rng(9);
    std::vector<float> perSample(samples * 3);
    for (float& v : perSample) v = float(rng() % 10000) / 100.0f;
    const VertexGather gather(w, samples);
    std::vector<float> out(vertices * 3, -1.0f);
    std::vector<Float4> scratch;
    gather.apply(perSample, out, scratch);
    for (std::uint32_t v = 0; v < vertices; ++v)
        for (int c = 0; c < 3; ++c) {
            double sum = 0.0;
            for (std::uint32_t e = w.offsets[v]; e < w.offsets[v + 1]; ++e) sum += double(w.weights[e]) * perSample[3 * w.samples[e] + c];
            ASSERT_NEAR(out[3 * v + c], sum, 1e-5 * (1.0 + sum)) << samples << " samples, vertex " << v << " channel " << c;
        }
    EXPECT_EQ(out[0], 0.0f);  // no weights: no radiance
}

TEST(VertexGather, EqualsThePlainSumInTheVerticesOwnOrder) {
    for (std::uint32_t samples : {500u, 65536u, 65537u}) expectThePlainSum(samples);
}

// Two signals in one pass give, bit for bit, what two passes give.
TEST(VertexGather, TwoSignalsAtOnceAreTwoGathers) {
    const std::uint32_t samples = 500, vertices = 3000;
    const VertexWeights w = randomWeights(vertices, samples, 7);
    std::mt19937 rng(11);
    std::vector<float> a(samples * 3), b(samples * 3);
    for (float& v : a) v = float(rng() % 10000) / 100.0f;
    for (float& v : b) v = float(rng() % 10000) / 7.0f;
    const VertexGather gather(w, samples);
    std::vector<Float4> scratch;
    std::vector<float> outA(vertices * 3), outB(vertices * 3), aloneA(vertices * 3), aloneB(vertices * 3);
    gather.apply(a, b, outA, outB, scratch);
    gather.apply(a, aloneA, scratch);
    gather.apply(b, aloneB, scratch);
    EXPECT_EQ(outA, aloneA);
    EXPECT_EQ(outB, aloneB);
    EXPECT_NE(outA, outB);
    std::vector<float> shortB(vertices * 3 - 3);
    EXPECT_THROW(gather.apply(a, b, outA, shortB, scratch), Error);
}

TEST(VertexGather, RefusesASampleOutOfRangeAndMismatchedSizes) {
    VertexWeights w = randomWeights(20, 50, 3);
    EXPECT_THROW(VertexGather(w, 10), Error);  // indices up to 49 for 10 samples
    const VertexGather gather(w, 50);
    std::vector<float> perSample(50 * 3, 1.0f), out(19 * 3);
    std::vector<Float4> scratch;
    EXPECT_THROW(gather.apply(perSample, out, scratch), Error);
    w.offsets.back() += 1;
    EXPECT_THROW(VertexGather(w, 50), Error);
}

}  // namespace
}  // namespace opal
