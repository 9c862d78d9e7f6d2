#include "delegate/relight/vertex_gather.h"

#include "schema/asset/sidecar_checks.h"
#include "schema/error.h"
#include "schema/target_clones.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>
#include <string>

namespace opal {

namespace {

// The CSR checks a sidecar's reader makes (sidecar_checks.h), for weights that come from
// elsewhere too (tests, synthetic assets); the sums to 1 are the reader's alone.
void checkWeights(const VertexWeights& weights, std::size_t samples) {
    if (weights.offsets.empty()) return;  // no vertices
    constexpr std::string_view context = "vertex gather";
    if (weights.samples.size() != weights.weights.size())
        throw Error(std::string(context) + ": " + std::to_string(weights.samples.size()) + " sample indices but " +
                    std::to_string(weights.weights.size()) + " weights");
    const std::span<const std::uint32_t> offsets = weights.offsets;
    sidecar::checkOffsets(offsets, offsets.size() - 1, weights.samples.size(), context, "vertex offsets");
    sidecar::checkIndices(offsets, std::span<const std::uint32_t>(weights.samples), samples, false, context,
                          "vertex samples");
}

// The sample a vertex leans on most (its first on a tie; 0 for a vertex without weights).
std::uint32_t heaviestSample(const VertexWeights& weights, std::size_t v) {
    std::uint32_t best = 0;
    float bestWeight = -1.0f;
    for (std::uint32_t e = weights.offsets[v]; e < weights.offsets[v + 1]; ++e)
        if (weights.weights[e] > bestWeight) {
            bestWeight = weights.weights[e];
            best = weights.samples[e];
        }
    return best;
}

}  // namespace

VertexGather::VertexGather(const VertexWeights& weights, std::size_t samples) : samples_(samples) {
    checkWeights(weights, samples);
    const std::size_t vertices = weights.offsets.empty() ? 0 : weights.offsets.size() - 1;
    std::vector<std::uint32_t> key(vertices);
    for (std::size_t v = 0; v < vertices; ++v) key[v] = heaviestSample(weights, v);
    vertex_.resize(vertices);
    std::iota(vertex_.begin(), vertex_.end(), 0u);
    std::stable_sort(vertex_.begin(), vertex_.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
    offsets_.reserve(vertices + 1);
    offsets_.push_back(0);
    sample_ = CompactIndices(samples);
    sample_.reserve(weights.samples.size());
    weight_.reserve(weights.weights.size());
    for (std::uint32_t v : vertex_) {
        for (std::uint32_t e = weights.offsets[v]; e < weights.offsets[v + 1]; ++e) {
            sample_.push_back(weights.samples[e]);  // checked below samples
            weight_.push_back(weights.weights[e]);
        }
        offsets_.push_back(std::uint32_t(weight_.size()));
    }
}

void VertexGather::checkSizes(std::span<const float> perSample, std::span<const float> out) const {
    if (perSample.size() != samples_ * 3 || out.size() != vertex_.size() * 3)
        throw Error("vertex gather: " + std::to_string(perSample.size()) + " sample values and " +
                    std::to_string(out.size()) + " vertex values for " + std::to_string(samples_) + " samples and " +
                    std::to_string(vertex_.size()) + " vertices (RGB each)");
}

template <int S>
void VertexGather::gather(const std::span<const float> (&perSample)[S], const std::span<float> (&out)[S],
                          std::vector<Float4>& scratch) const {
    for (int s = 0; s < S; ++s) checkSizes(perSample[s], out[s]);
    // The samples' RGB padded to four lanes, the S signals of a sample side by side: one
    // aligned load per weight and signal, from one cache line.
    scratch.resize(samples_ * S);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples_, 8192), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i)
            for (int s = 0; s < S; ++s) {
                const float* p = perSample[s].data() + 3 * i;
                scratch[S * i + s] = Float4{p[0], p[1], p[2], 0.0f};
            }
    });
    sample_.withData([&](const auto* sample) { gatherVertices<S>(sample, scratch.data(), out); });
}

namespace {

// The sums over vertices [begin, end) of the visiting order. Sample indices are 16 bits
// when they fit: a quarter fewer bytes than 32-bit indices, and the weights and indices are
// most of what a material edit's gather reads. Compiled for AVX2 too (target_clones.h):
// there the weight is broadcast from memory and every operation has three operands, which
// took a material edit's gather on the 65,536-sample bunny from 0.44-0.47 to 0.40-0.42 ms
// (the baseline build spends a shuffle and a copy a weight).
template <int S, typename Index>
OPAL_TARGET_CLONES("avx2", "default") void gatherRange(std::size_t begin, std::size_t end, const std::uint32_t* offsets,
                                    const std::uint32_t* vertex, const Index* sample, const float* weight,
                                    const Float4* padded, float* const (&to)[S]) {
    for (std::size_t i = begin; i != end; ++i) {
        // Two sums per signal: each add waits for the one before it, and a vertex has
        // about 8 weights.
        Float4 even[S] = {}, odd[S] = {};
        std::uint32_t e = offsets[i];
        const std::uint32_t stop = offsets[i + 1];
        for (; e + 2 <= stop; e += 2)
            for (int s = 0; s < S; ++s) {
                even[s] += weight[e] * padded[S * std::size_t(sample[e]) + s];
                odd[s] += weight[e + 1] * padded[S * std::size_t(sample[e + 1]) + s];
            }
        if (e < stop)
            for (int s = 0; s < S; ++s) even[s] += weight[e] * padded[S * std::size_t(sample[e]) + s];
        for (int s = 0; s < S; ++s) {
            const Float4 sum = even[s] + odd[s];
            float* v = to[s] + 3 * std::size_t(vertex[i]);
            v[0] = sum[0];
            v[1] = sum[1];
            v[2] = sum[2];
        }
    }
}

}  // namespace

template <int S, typename Index>
void VertexGather::gatherVertices(const Index* sample, const Float4* padded, const std::span<float> (&out)[S]) const {
    float* to[S];
    for (int s = 0; s < S; ++s) to[s] = out[s].data();
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertex_.size(), 4096), [&](const tbb::blocked_range<std::size_t>& r) {
        gatherRange<S>(r.begin(), r.end(), offsets_.data(), vertex_.data(), sample, weight_.data(), padded, to);
    });
}

void VertexGather::apply(std::span<const float> perSample, std::span<float> out, std::vector<Float4>& scratch) const {
    gather<1>({perSample}, {out}, scratch);
}

void VertexGather::apply(std::span<const float> perSampleA, std::span<const float> perSampleB, std::span<float> outA,
                         std::span<float> outB, std::vector<Float4>& scratch) const {
    gather<2>({perSampleA, perSampleB}, {outA, outB}, scratch);
}

std::size_t VertexGather::memoryBytes() const {
    return (vertex_.capacity() + offsets_.capacity()) * sizeof(std::uint32_t) + sample_.memoryBytes() +
           weight_.capacity() * sizeof(float);
}

}  // namespace opal
