#include "bake/transfer_stages.h"

#include "schema/error.h"
#include "schema/wavelet/cdf97.h"
#include "schema/wavelet/haar.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace opal {

namespace {

// lambda_k / lambda_1 per basis function, clamped at 0 (all 1 for a zero spectrum): how
// much T_k matters in L = sum_k s_k T_k E, for both steps' weighting.
std::vector<double> relativeEigenvalues(const ProfileBasis& basis) {
    const std::span<const double> lambda = basis.eigenvalues();
    std::vector<double> relative(lambda.size(), 1.0);
    if (lambda[0] > 0.0)
        for (std::size_t k = 0; k < lambda.size(); ++k) relative[k] = std::max(lambda[k], 0.0) / lambda[0];
    return relative;
}

// How many Haar coefficients a row of each T_k keeps: averagePerRow on average over k
// (TransferSettings says how it is chosen), split in proportion to
// (lambda_k / lambda_1)^(1/4): T_k contributes to L = sum_k s_k T_k E with s_k of RMS
// size sqrt(lambda_k), so the first matrices need their rows kept more finely than the
// last. At least one per row, at most N. Measured at the bake's defaults (16,384 samples), transfer
// error with an equal split / this one: bunny 1.06 / 0.87%, Spot 0.82 / 0.67%, candle
// 0.72 / 0.57%, sidecars within 8%; exponent 1/2 starves the middle k (bunny 1.51%).
std::vector<std::uint32_t> step1Budgets(double averagePerRow, std::size_t n, const ProfileBasis& basis) {
    std::vector<double> share = relativeEigenvalues(basis);
    for (double& s : share) s = std::pow(s, 0.25);
    // Water-filling: a matrix's share is capped at the whole row (N) and what it cannot take
    // goes to the others in the same proportions, so keep 1 keeps every row whole.
    const double rowLength = double(n);
    double budget = std::min(averagePerRow, rowLength) * double(share.size());
    std::vector<double> count(share.size(), 0.0);
    std::vector<bool> full(share.size(), false);
    for (bool capped = true; capped;) {
        capped = false;
        double open = 0.0;
        for (std::size_t k = 0; k < share.size(); ++k)
            if (!full[k]) open += share[k];
        for (std::size_t k = 0; k < share.size(); ++k)
            if (!full[k] && open > 0.0 && budget * share[k] / open >= rowLength) {
                full[k] = capped = true;
                count[k] = rowLength;
                budget -= rowLength;
            }
        if (!capped)
            for (std::size_t k = 0; k < share.size(); ++k)
                if (!full[k] && open > 0.0) count[k] = budget * share[k] / open;
    }
    std::vector<std::uint32_t> perRow;
    for (double c : count) perRow.push_back(std::uint32_t(std::clamp(std::ceil(c), 1.0, rowLength)));
    return perRow;
}

struct ColumnScratch {
    std::vector<float> dense;
    std::vector<std::uint32_t> charts;
};

tbb::enumerable_thread_specific<ColumnScratch> columnScratch(std::size_t n) {
    return tbb::enumerable_thread_specific<ColumnScratch>(
        [n] { return ColumnScratch{std::vector<float>(n, 0.0f), {}}; });
}

// Transforms column j of the retained matrix along the output dimension (CDF 9/7 per
// chart) into `dense`, and calls visit(p, coefficient, energy) for every coefficient of
// the charts the column touches, energy = c^2 g_p columnWeight.
template <typename Visit>
void transformColumn(const Step1Columns& cols, std::size_t j, const ChartLayout& layout,
                     std::span<const float> normsSquared, float columnWeight, std::vector<float>& dense,
                     std::vector<std::uint32_t>& charts, Visit&& visit) {
    const std::size_t cellsPerChart = layout.cellsPerChart();
    charts.clear();
    for (std::uint64_t e = cols.offsets[j - cols.first]; e < cols.offsets[j - cols.first + 1]; ++e) {
        dense[cols.row[e]] = cols.value[e];
        const auto chart = std::uint32_t(cols.row[e] / cellsPerChart);
        if (charts.empty() || charts.back() != chart) charts.push_back(chart);
    }
    for (std::uint32_t chart : charts) {
        std::span<float> grid(dense.data() + chart * cellsPerChart, cellsPerChart);
        cdf97Forward2D(grid, layout.size());
        for (std::size_t q = 0; q < cellsPerChart; ++q) {
            const float c = grid[q];
            if (c != 0.0f) visit(chart * cellsPerChart + q, c, c * c * normsSquared[q] * columnWeight);
            grid[q] = 0.0f;
        }
    }
}

float columnWeight(const ChartLayout& layout, const Step2Weights& weights, std::size_t k, std::size_t j) {
    return float(double(weights.columnArea[j % layout.cellsPerChart()]) * weights.basis[k]);
}

}  // namespace

TransferPlan planTransfer(std::size_t sampleCount, const ChartLayout& layout, const ProfileBasis& basis,
                          const TransferSettings& settings) {
    const std::size_t n = sampleCount;
    if (n != layout.cells())
        throw Error("transfer: " + std::to_string(n) + " samples do not fill the chart layout of " +
                    std::to_string(layout.cells()) + " cells");
    if (!(settings.keepFraction > 0.0 && settings.keepFraction <= 1.0))
        throw Error("transfer: keep fraction must be in (0, 1], got " + std::to_string(settings.keepFraction));
    if (!(settings.energyFraction > 0.0 && settings.energyFraction <= 1.0))
        throw Error("transfer: energy fraction must be in (0, 1], got " + std::to_string(settings.energyFraction));
    if (basis.K() > 64) throw Error("transfer: at most 64 basis functions are supported");
    TransferPlan plan;
    plan.layout = layout;
    plan.settings = settings;
    plan.fractionPerRow = settings.keepFraction * double(n);
    const double averagePerRow = std::max(plan.fractionPerRow, double(settings.minPerRow));
    plan.perRow = step1Budgets(averagePerRow, n, basis);
    return plan;
}

std::vector<Step1Rows> compressRows(const TransferPlan& plan, const TransferSamples& samples,
                                    const BasisLookup& lookup, std::size_t begin, std::size_t end,
                                    ProgressSink* progress, const CancelToken& cancel) {
    const std::size_t n = samples.size();
    const int K = lookup.K();
    const ChartLayout& layout = plan.layout;
    if (n != plan.n() || std::size_t(K) != plan.K() || begin > end || end > n)
        throw Error("transfer step 1: rows " + std::to_string(begin) + ".." + std::to_string(end) + " of " +
                    std::to_string(n) + " samples do not fit the plan of " + std::to_string(plan.n()) +
                    " samples and K = " + std::to_string(plan.K()));
    const std::size_t Q = samples.harmonics.size();
    std::vector<Step1Rows> rows(K);
    for (int k = 0; k < K; ++k) {
        Step1Rows& r = rows[std::size_t(k)];
        r.perRow = plan.perRow[std::size_t(k)];
        r.column.resize((end - begin) * r.perRow);
        r.value.resize((end - begin) * r.perRow);
        r.harmonics.resize((end - begin) * Q);
    }
    StageScope stage(progress, "transfer step 1 (Haar)", end - begin);
    const std::size_t stride = transferRowStride(n);  // rows of K apart in cache sets
    const std::size_t rowsSize = std::size_t(K - 1) * stride + n;
    tbb::enumerable_thread_specific<std::vector<float>> scratch(
        [&] { return std::vector<float>(rowsSize + n + std::size_t(K) * Q); });
    const std::size_t cellsPerChart = layout.cellsPerChart();
    // Rows keep the largest |c_j| area_j^0.75 rather than the largest |c_j| (area_j: the
    // cells Haar function j covers; a light's coefficient E^_j grows with area_j where the
    // irradiance is smooth at the function's scale, with sqrt(area_j) across an edge).
    // Measured, transfer error at the bake's defaults (16,384 samples), area_j^p for
    // p = 0.5 / 0.75 / 1: bunny 1.02 / 1.06 / 1.33%, Spot 1.06 / 0.82 / 0.94%, candle
    // 0.86 / 0.72 / 0.77%; p = 0 (plain |c_j|) was 17% on a 4,096-sample candle.
    std::vector<float> importance = haarSupportCells(layout.size());
    for (float& a : importance) a = std::pow(a, 0.75f);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end, 8), [&](const auto& range) {
        cancel.throwIfRequested();
        std::vector<float>& buf = scratch.local();
        const std::span<float> all(buf.data(), rowsSize);
        const std::span<float> weighted(buf.data() + rowsSize, n);
        const std::span<float> harmonics(buf.data() + rowsSize + n, std::size_t(K) * Q);
        for (std::size_t o = range.begin(); o != range.end(); ++o) {
            transferRow(o, samples, lookup, all, stride);
            for (int k = 0; k < K; ++k) all[std::size_t(k) * stride + o] = 0.0f;  // the self term: at run time
            harmonicRow(all, stride, std::size_t(K), samples, harmonics);
            for (int k = 0; k < K; ++k) {
                const std::span<float> row(buf.data() + std::size_t(k) * stride, n);
                std::copy_n(harmonics.data() + std::size_t(k) * Q, Q, rows[k].harmonics.begin() + (o - begin) * Q);
                haarForwardCharts(row, layout);
                for (std::size_t c = 0; c < n; c += cellsPerChart)
                    for (std::size_t q = 0; q < cellsPerChart; ++q) weighted[c + q] = row[c + q] * importance[q];
                const std::size_t at = (o - begin) * rows[k].perRow;
                const SparseVector kept = keepLargest(weighted, rows[k].perRow);
                std::copy(kept.indices.begin(), kept.indices.end(), rows[k].column.begin() + at);
                for (std::size_t e = 0; e < kept.size(); ++e) rows[k].value[at + e] = row[kept.indices[e]];
            }
        }
        stage.advance(range.size());
    });
    return rows;
}

std::vector<float> gatherHarmonics(const std::vector<Step1Rows>& rows, std::size_t begin, std::size_t end) {
    const std::size_t K = rows.size(), count = end - begin;
    const std::size_t Q = rows.empty() || count == 0 ? 0 : rows[0].harmonics.size() / count;
    std::vector<float> out(count * K * Q);
    for (std::size_t k = 0; k < K; ++k) {
        if (rows[k].harmonics.size() != count * Q)
            throw Error("transfer: matrix " + std::to_string(k) + " has " + std::to_string(rows[k].harmonics.size()) +
                        " harmonic values, expected " + std::to_string(count) + " rows x " + std::to_string(Q));
        for (std::size_t o = 0; o < count; ++o)
            std::copy_n(rows[k].harmonics.data() + o * Q, Q, out.data() + (o * K + k) * Q);
    }
    return out;
}

// Step 2 ranks the 9/7 coefficients of all K matrices together by a weighted energy,
//   e = c^2 g_p a_j lambda_k / lambda_1,
// for the coefficient c at output position p of column j of T_k: g_p the squared norm of
// the 9/7 synthesis function at p (9/7 is biorthogonal, cdf97.h), a_j the support area of
// Haar function j (as in step 1: what the light's coefficient grows with), lambda_k the
// PCA eigenvalue of b_k (the mean square of s_k over the training materials, up to a
// common factor: how much T_k matters in L = sum_k s_k T_k E). It keeps the most
// energetic coefficients until `energyFraction` of the total is reached; the relative
// error of the transfer is then about sqrt(1 - energyFraction). Measured on a 16,384-
// sample candle (keep 1%, energy 0.9999): each matrix thresholded on its own by c^2 g_p,
// 1.46% error in a 156 MB sidecar; all together by the weighted energy, 0.92% in 36 MB.
Step2Weights step2Weights(const ChartLayout& layout, const ProfileBasis& basis) {
    return {cdf97SynthesisNormsSquared(layout.size()), haarSupportCells(layout.size()), relativeEigenvalues(basis)};
}

// The grid kept values are stored on (schema/asset/transfer_value_grid.h): a quarter of
// the smallest kept weighted amplitude tau, per matrix in units of its own values; 0
// (exact) when everything is kept. Measured on a 16,384-sample candle at energy 0.9999
// (transfer error unrounded 0.92%; transfer chunk 14.0 MB as half floats): steps of
// tau / 4, 0.935% in 9.4 MB; tau / 2, 0.985% in 8.8 MB; tau, 1.05% in 8.2 MB.
std::vector<double> valueSteps(int minBin, const Step2Weights& weights) {
    std::vector<double> steps(weights.basis.size(), 0.0);
    if (minBin == 0) return steps;
    const double tau = std::sqrt(double(binLowerEdge(minBin)));
    for (std::size_t k = 0; k < steps.size(); ++k)
        if (weights.basis[k] > 0.0) steps[k] = 0.25 * tau / std::sqrt(weights.basis[k]);
    return steps;
}

EnergyHistogram histogramOfColumns(const Step1Columns& columns, const ChartLayout& layout,
                                   const Step2Weights& weights, std::size_t k, const StageScope& stage,
                                   const CancelToken& cancel) {
    auto scratch = columnScratch(layout.cells());
    const std::size_t end = columns.first + columns.count();
    // Any split gives the same sums (energy_histogram.h); the fixed grain keeps the
    // partial histograms few.
    return tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(columns.first, end, 256), EnergyHistogram{},
        [&](const tbb::blocked_range<std::size_t>& range, EnergyHistogram h) {
            cancel.throwIfRequested();
            ColumnScratch& s = scratch.local();
            for (std::size_t j = range.begin(); j != range.end(); ++j)
                transformColumn(columns, j, layout, weights.synthesisNorms, columnWeight(layout, weights, k, j),
                                s.dense, s.charts, [&](std::size_t, float, float e) { h.add(e); });
            stage.advance(range.size());
            return h;
        },
        [](EnergyHistogram a, const EnergyHistogram& b) {
            a.add(b);
            return a;
        });
}

KeptColumns keptColumns(const Step1Columns& columns, const ChartLayout& layout, const Step2Weights& weights,
                        std::size_t k, int minBin, const StageScope& stage, const CancelToken& cancel) {
    // Chunks of consecutive columns, each kept into its own flat arrays in parallel, then
    // joined in column order.
    constexpr std::size_t kChunk = 256;
    const std::size_t chunks = (columns.count() + kChunk - 1) / kChunk;
    std::vector<KeptColumns> parts(chunks);
    auto scratch = columnScratch(layout.cells());
    tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t chunk) {
        cancel.throwIfRequested();
        ColumnScratch& s = scratch.local();
        KeptColumns& part = parts[chunk];
        const std::size_t begin = columns.first + chunk * kChunk;
        const std::size_t end = std::min(begin + kChunk, columns.first + columns.count());
        for (std::size_t j = begin; j != end; ++j) {
            transformColumn(columns, j, layout, weights.synthesisNorms, columnWeight(layout, weights, k, j), s.dense,
                            s.charts, [&](std::size_t p, float c, float e) {
                                if (energyBin(e) < minBin) return;
                                part.row.push_back(std::uint32_t(p));
                                part.value.push_back(c);
                            });
            part.offsets.push_back(part.row.size());
        }
        stage.advance(end - begin);
    });
    KeptColumns kept;
    kept.first = columns.first;
    std::size_t total = 0;
    for (const KeptColumns& part : parts) total += part.row.size();
    kept.offsets.reserve(columns.count() + 1);
    kept.row.reserve(total);
    kept.value.reserve(total);
    for (KeptColumns& part : parts) {
        const std::uint64_t base = kept.row.size();
        for (std::size_t c = 1; c < part.offsets.size(); ++c) kept.offsets.push_back(base + part.offsets[c]);
        kept.row.insert(kept.row.end(), part.row.begin(), part.row.end());
        kept.value.insert(kept.value.end(), part.value.begin(), part.value.end());
        part = KeptColumns{};
    }
    return kept;
}

KeptMatrixAssembler::KeptMatrixAssembler(std::size_t n) {
    matrix_.rows = matrix_.cols = std::uint32_t(n);
    matrix_.rowOffsets.assign(n + 1, 0);
}

void KeptMatrixAssembler::count(const KeptColumns& block) {
    for (const std::uint32_t p : block.row) {
        if (p >= matrix_.rows)
            throw Error("transfer step 2: kept coefficient at output " + std::to_string(p) + " of " +
                        std::to_string(matrix_.rows));
        ++matrix_.rowOffsets[p + 1];
    }
}

void KeptMatrixAssembler::fill(const KeptColumns& block) {
    if (!filling_) {
        for (std::size_t p = 0; p < matrix_.rows; ++p) matrix_.rowOffsets[p + 1] += matrix_.rowOffsets[p];
        matrix_.columns.resize(matrix_.rowOffsets.back());
        matrix_.values.resize(matrix_.rowOffsets.back());
        cursor_.assign(matrix_.rowOffsets.begin(), matrix_.rowOffsets.end() - 1);
        filling_ = true;
    }
    for (std::size_t c = 0; c < block.count(); ++c)
        for (std::uint64_t e = block.offsets[c]; e < block.offsets[c + 1]; ++e) {
            const std::uint32_t p = block.row[e];
            if (p >= matrix_.rows || cursor_[p] >= matrix_.rowOffsets[p + 1])
                throw Error("transfer step 2: the kept columns filled differ from the ones counted (output " +
                            std::to_string(p) + ")");
            const std::uint64_t at = cursor_[p]++;
            matrix_.columns[at] = std::uint32_t(block.first + c);
            matrix_.values[at] = block.value[e];
        }
}

SparseMatrix KeptMatrixAssembler::take() {
    if (!filling_) fill(KeptColumns{});
    for (std::size_t p = 0; p < matrix_.rows; ++p)
        if (cursor_[p] != matrix_.rowOffsets[p + 1])
            throw Error("transfer step 2: output " + std::to_string(p) + " was counted but not filled");
    return std::move(matrix_);
}

CompressedTransfer transferShell(const TransferPlan& plan, int minBin, const Step2Weights& weights) {
    CompressedTransfer out;
    out.valueSteps = valueSteps(minBin, weights);
    out.keepFraction = plan.settings.keepFraction;
    out.energyFraction = plan.settings.energyFraction;
    out.selfTerm = SelfTerm::AtRunTime;
    return out;
}

TransferStats transferStats(const TransferPlan& plan, const CompressedTransfer& transfer, double energyKept) {
    TransferStats stats;
    const std::uint64_t n = plan.n();
    const std::uint64_t entryBytes = sizeof(std::uint32_t) + sizeof(float);
    stats.rawBytes = n * n * plan.K() * sizeof(float);
    for (std::uint32_t p : plan.perRow) stats.step1Bytes += n * p * entryBytes;
    for (const SparseMatrix& m : transfer.perBasis) stats.step2NonZeros += m.nonZeros();
    stats.step2Bytes = stats.step2NonZeros * entryBytes;
    stats.energyKept = energyKept;
    for (std::uint32_t p : plan.perRow) stats.step1PerRow += double(p) / double(plan.perRow.size());
    stats.step1Floor = plan.fractionPerRow < double(plan.settings.minPerRow);
    return stats;
}

}  // namespace opal
