#include "bench/transfer_step_gathers.h"

#include "bake/transfer_row.h"
#include "bake/transfer_stages.h"
#include "schema/asset/normal_harmonics.h"
#include "schema/asset/self_term.h"
#include "schema/error.h"
#include "schema/scatter/profile_projection.h"
#include "schema/wavelet/haar.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <array>
#include <numbers>
#include <numeric>
#include <string>
#include <utility>

namespace opal::bench {

namespace {

constexpr std::size_t kRowBlock = 1024;  // step 1's rows held at once

struct Weights {
    std::array<std::vector<double>, 3> s;  // s_k / pi per channel
    std::vector<float> self;               // R_disk / pi, samples x 3
};

// The engine's weights, after checking the inputs.
Weights engineWeights(const TranslucentAsset& asset, const Material& material, std::span<const float> irradiance) {
    const std::size_t n = asset.samples.size();
    if (irradiance.size() != 3 * n)
        throw Error("step gathers: " + std::to_string(irradiance.size()) + " irradiance values for " +
                    std::to_string(n) + " RGB samples");
    if (asset.transfer.selfTerm != SelfTerm::AtRunTime)
        throw Error("step gathers: the asset's self term is in its transfer (a sidecar before 2.3); rebake it");
    const Material clamped = asset.range.clamp(material, nullptr);
    Weights w;
    w.s = ProfileProjection(asset.basis, profileFitRadius(asset)).project(clamped);
    for (auto& channel : w.s)
        for (double& s : channel) s /= std::numbers::pi;
    w.self.resize(3 * asset.samples.size());
    selfTermReflectance(asset.samples, asset.unitsPerMm, clamped, w.self);
    for (float& r : w.self) r = float(r / std::numbers::pi);
    return w;
}

// L_o = sum_k (s_k / pi) y_k + (R_disk / pi) E_o per channel into out[0, 3), y: K x 3 for
// output o.
void radianceAt(const Weights& w, std::span<const double> y, std::span<const float> e, std::size_t o, float* out) {
    const std::size_t K = w.s[0].size();
    for (int c = 0; c < 3; ++c) {
        double sum = 0.0;
        for (std::size_t k = 0; k < K; ++k) sum += w.s[c][k] * y[3 * k + c];
        out[c] = float(sum + double(w.self[3 * o + c]) * e[3 * o + c]);
    }
}

// The outputs to replay: `outputs`, or every sample when it is empty.
std::vector<std::uint32_t> outputList(std::size_t samples, std::span<const std::uint32_t> outputs) {
    if (!outputs.empty()) {
        for (const std::uint32_t o : outputs)
            if (o >= samples)
                throw Error("step gathers: output " + std::to_string(o) + " of " + std::to_string(samples) +
                            " samples");
        return {outputs.begin(), outputs.end()};
    }
    std::vector<std::uint32_t> all(samples);
    std::iota(all.begin(), all.end(), 0u);
    return all;
}

std::vector<float> losslessRows(const TransferSamples& mm, const BasisLookup& lookup, const Weights& w,
                                std::span<const float> e, std::span<const std::uint32_t> outputs) {
    const std::size_t n = mm.size(), K = std::size_t(lookup.K());
    std::vector<float> out(3 * outputs.size());
    tbb::enumerable_thread_specific<std::vector<float>> rows([&] { return std::vector<float>(K * n); });
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, outputs.size(), 16), [&](const tbb::blocked_range<std::size_t>& r) {
        std::vector<float>& t = rows.local();
        std::vector<double> y(3 * K);
        for (std::size_t slot = r.begin(); slot != r.end(); ++slot) {
            const std::size_t o = outputs[slot];
            transferRow(o, mm, lookup, t);
            std::fill(y.begin(), y.end(), 0.0);
            for (std::size_t k = 0; k < K; ++k)
                for (std::size_t i = 0; i < n; ++i) {
                    if (i == o) continue;  // the self term, added at run time
                    for (int c = 0; c < 3; ++c) y[3 * k + c] += double(t[k * n + i]) * e[3 * i + c];
                }
            radianceAt(w, y, e, o, out.data() + 3 * slot);
        }
    });
    return out;
}

// E's Haar coefficients per chart, channel-interleaved as E.
std::vector<float> haarOfIrradiance(const ChartLayout& layout, std::span<const float> e) {
    std::vector<float> we(e.begin(), e.end());
    haarForwardCharts(std::span<float>(we), layout, 3);
    return we;
}

// [first, last) slots of `outputs` whose samples are consecutive, at most `most` each.
std::vector<std::pair<std::size_t, std::size_t>> consecutiveRuns(std::span<const std::uint32_t> outputs,
                                                                 std::size_t most) {
    std::vector<std::pair<std::size_t, std::size_t>> runs;
    for (std::size_t first = 0; first < outputs.size();) {
        std::size_t last = first + 1;
        while (last < outputs.size() && last - first < most && outputs[last] == outputs[last - 1] + 1) ++last;
        runs.emplace_back(first, last);
        first = last;
    }
    return runs;
}

std::vector<float> step1Rows(const TranslucentAsset& asset, const TransferSamples& mm, const BasisLookup& lookup,
                             const TransferSettings& settings, const Weights& w, std::span<const float> e,
                             std::span<const std::uint32_t> outputs) {
    const std::size_t n = mm.size(), K = std::size_t(lookup.K());
    const TransferPlan plan = planTransfer(n, asset.layout, asset.basis, settings);
    // As the engine: with the harmonic transfer, step 1 carries only E's residual after its
    // smooth part, whose transfer is exact (docs/ARCHITECTURE.md#harmonic-transfer).
    // The rows' harmonic transfer is of mm's set, harmonicSetFor(asset.samples): the
    // asset's own set when it was baked with 36 functions.
    const bool split = !asset.transfer.harmonics.empty();
    const std::size_t Q = mm.harmonicSet.count;
    std::vector<float> a, residual(e.begin(), e.end());
    if (split) {
        const HarmonicFit fit(asset.samples, mm.harmonicSet);
        a = fit.coefficients(e, 3);
        fit.residual(e, 3, a, residual, 3);
    }
    const std::vector<float> we = haarOfIrradiance(asset.layout, residual);
    std::vector<float> out(3 * outputs.size());
    // Runs of consecutive samples (every sample: blocks of kRowBlock rows, one after the other
    // with compressRows parallel over each; a random subset: mostly single rows, in parallel).
    const std::vector<std::pair<std::size_t, std::size_t>> runs = consecutiveRuns(outputs, kRowBlock);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, runs.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t run = r.begin(); run != r.end(); ++run) {
            const auto [first, last] = runs[run];  // slots of `outputs`
            const std::size_t begin = outputs[first], end = begin + (last - first);
            const std::vector<Step1Rows> rows = compressRows(plan, mm, lookup, begin, end, nullptr, CancelToken());
            std::vector<double> y((end - begin) * 3 * K, 0.0);  // y_k = T_k E for the run's rows
            for (std::size_t k = 0; k < K; ++k) {
                forEachRowEntry(rows[k], begin, [&](std::uint32_t o, std::uint32_t j, float value) {
                    for (int c = 0; c < 3; ++c)
                        y[((o - begin) * K + k) * 3 + c] += double(value) * we[3 * std::size_t(j) + c];
                });
                if (!split) continue;
                for (std::size_t o = begin; o < end; ++o)
                    for (std::size_t q = 0; q < Q; ++q)
                        for (int c = 0; c < 3; ++c)
                            y[((o - begin) * K + k) * 3 + c] +=
                                double(a[q * 3 + c]) * rows[k].harmonics[(o - begin) * Q + q];
            }
            for (std::size_t o = begin; o < end; ++o)
                radianceAt(w, std::span<const double>(y).subspan((o - begin) * 3 * K, 3 * K), e, o,
                           out.data() + 3 * (first + (o - begin)));
        }
    });
    return out;
}

}  // namespace

std::vector<float> losslessGather(const TranslucentAsset& asset, const Material& material,
                                  std::span<const float> irradiance, std::span<const std::uint32_t> outputs) {
    const Weights w = engineWeights(asset, material, irradiance);
    return losslessRows(toTransferSamples(asset.samples, asset.unitsPerMm), BasisLookup(asset.basis), w, irradiance,
                        outputList(asset.samples.size(), outputs));
}

std::vector<float> step1Gather(const TranslucentAsset& asset, const Material& material,
                               std::span<const float> irradiance, const TransferSettings& settings,
                               std::span<const std::uint32_t> outputs) {
    const Weights w = engineWeights(asset, material, irradiance);
    return step1Rows(asset, toTransferSamples(asset.samples, asset.unitsPerMm), BasisLookup(asset.basis), settings, w,
                     irradiance, outputList(asset.samples.size(), outputs));
}

}  // namespace opal::bench
