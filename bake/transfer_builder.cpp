#include "bake/transfer_builder.h"

#include "bake/transfer_row.h"

#include "schema/wavelet/cdf97.h"
#include "schema/wavelet/haar.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <vector>

namespace opal {

namespace {

// The retained Haar coefficients of step 1: the same count for every row.
struct Step1Rows {
    std::uint32_t perRow = 0;
    std::vector<std::uint32_t> column;  // N x perRow, ascending within a row
    std::vector<float> value;
};

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

std::vector<Step1Rows> compressLightDimension(const TransferSamples& samples, const ChartLayout& layout,
                                              const BasisLookup& lookup, std::span<const std::uint32_t> perRow,
                                              ProgressSink* progress, const CancelToken& cancel) {
    const std::size_t n = samples.size();
    const int K = lookup.K();
    std::vector<Step1Rows> rows(K);
    for (int k = 0; k < K; ++k) {
        Step1Rows& r = rows[std::size_t(k)];
        r.perRow = perRow[std::size_t(k)];
        r.column.resize(n * r.perRow);
        r.value.resize(n * r.perRow);
    }
    StageScope stage(progress, "transfer step 1 (Haar)", n);
    const std::size_t stride = transferRowStride(n);  // rows of K apart in cache sets
    const std::size_t rowsSize = std::size_t(K - 1) * stride + n;
    tbb::enumerable_thread_specific<std::vector<float>> scratch([&] { return std::vector<float>(rowsSize + n); });
    const std::size_t cellsPerChart = layout.cellsPerChart();
    // Rows keep the largest |c_j| area_j^0.75 rather than the largest |c_j| (area_j: the
    // cells Haar function j covers; a light's coefficient E^_j grows with area_j where the
    // irradiance is smooth at the function's scale, with sqrt(area_j) across an edge).
    // Measured, transfer error at the bake's defaults (16,384 samples), area_j^p for
    // p = 0.5 / 0.75 / 1: bunny 1.02 / 1.06 / 1.33%, Spot 1.06 / 0.82 / 0.94%, candle
    // 0.86 / 0.72 / 0.77%; p = 0 (plain |c_j|) was 17% on a 4,096-sample candle.
    std::vector<float> importance = haarSupportCells(layout.size());
    for (float& a : importance) a = std::pow(a, 0.75f);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 8), [&](const auto& range) {
        cancel.throwIfRequested();
        std::vector<float>& buf = scratch.local();
        const std::span<float> all(buf.data(), rowsSize);
        const std::span<float> weighted(buf.data() + rowsSize, n);
        for (std::size_t o = range.begin(); o != range.end(); ++o) {
            transferRow(o, samples, lookup, all, stride);
            for (int k = 0; k < K; ++k) {
                const std::span<float> row(buf.data() + std::size_t(k) * stride, n);
                row[o] = 0.0f;  // the self term is added at run time (transfer_builder.h)
                haarForwardCharts(row, layout);
                for (std::size_t c = 0; c < n; c += cellsPerChart)
                    for (std::size_t q = 0; q < cellsPerChart; ++q) weighted[c + q] = row[c + q] * importance[q];
                const std::size_t at = o * rows[k].perRow;
                const SparseVector kept = keepLargest(weighted, rows[k].perRow);
                std::copy(kept.indices.begin(), kept.indices.end(), rows[k].column.begin() + at);
                for (std::size_t e = 0; e < kept.size(); ++e) rows[k].value[at + e] = row[kept.indices[e]];
            }
        }
        stage.advance(range.size());
    });
    return rows;
}

// Step 1's rows regrouped by column: column j holds (o, value) with o ascending.
struct Columns {
    std::vector<std::uint64_t> offsets;
    std::vector<std::uint32_t> row;
    std::vector<float> value;
};

// Rows with fewer nonzero coefficients than perRow are padded with zero values at column
// 0; those (and any true zeros) are dropped here, or a padding entry would overwrite the
// row's real coefficient at column 0.
Columns transpose(const Step1Rows& rows, std::size_t n) {
    Columns c;
    c.offsets.assign(n + 1, 0);
    for (std::size_t e = 0; e < rows.column.size(); ++e)
        if (rows.value[e] != 0.0f) ++c.offsets[rows.column[e] + 1];
    for (std::size_t j = 0; j < n; ++j) c.offsets[j + 1] += c.offsets[j];
    c.row.resize(c.offsets[n]);
    c.value.resize(c.offsets[n]);
    std::vector<std::uint64_t> cursor(c.offsets.begin(), c.offsets.end() - 1);
    for (std::size_t o = 0; o < n; ++o) {
        for (std::uint32_t e = 0; e < rows.perRow; ++e) {
            const std::size_t at = o * rows.perRow + e;
            if (rows.value[at] == 0.0f) continue;
            const std::uint64_t dst = cursor[rows.column[at]]++;
            c.row[dst] = std::uint32_t(o);
            c.value[dst] = rows.value[at];
        }
    }
    return c;
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
struct Step2Weights {
    std::vector<float> synthesisNorms;  // g_p per chart position
    std::vector<float> columnArea;      // a_j per chart position
    std::vector<double> basis;          // lambda_k / lambda_1
};

Step2Weights step2Weights(const ChartLayout& layout, const ProfileBasis& basis) {
    return {cdf97SynthesisNormsSquared(layout.size()), haarSupportCells(layout.size()), relativeEigenvalues(basis)};
}

// Energies are binned by the top bits of their float representation: for positive
// floats the bit pattern is monotonic, so bins are ordered (1/8 octave each).
constexpr int kEnergyBins = 1 << 12;
int energyBin(float e) { return int(std::bit_cast<std::uint32_t>(e) >> 19); }
float binLowerEdge(int bin) { return std::bit_cast<float>(std::uint32_t(bin) << 19); }

struct EnergyHistogram {
    std::vector<double> energy = std::vector<double>(kEnergyBins, 0.0);
    double total = 0.0;

    void add(const EnergyHistogram& o) {
        for (int b = 0; b < kEnergyBins; ++b) energy[b] += o.energy[b];
        total += o.total;
    }
};

// Transforms column j of the retained matrix along the output dimension (CDF 9/7 per
// chart) into `dense`, and calls visit(p, coefficient, energy) for every coefficient of
// the charts the column touches, energy = c^2 g_p columnWeight.
template <typename Visit>
void transformColumn(const Columns& cols, std::size_t j, const ChartLayout& layout,
                     std::span<const float> normsSquared, float columnWeight, std::vector<float>& dense,
                     std::vector<std::uint32_t>& charts, Visit&& visit) {
    const std::size_t cellsPerChart = layout.cellsPerChart();
    charts.clear();
    for (std::uint64_t e = cols.offsets[j]; e < cols.offsets[j + 1]; ++e) {
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

struct ColumnScratch {
    std::vector<float> dense;
    std::vector<std::uint32_t> charts;
};

// One matrix T_k of step 2: its step-1 columns, the weights, scratch space.
struct Step2Matrix {
    const Columns& cols;
    const ChartLayout& layout;
    const Step2Weights& weights;
    double basisWeight;  // lambda_k / lambda_1

    float columnWeight(std::size_t j) const {
        return float(double(weights.columnArea[j % layout.cellsPerChart()]) * basisWeight);
    }
};

EnergyHistogram histogramOfColumns(const Step2Matrix& m, const StageScope& stage, const CancelToken& cancel,
                                   tbb::enumerable_thread_specific<ColumnScratch>& scratch) {
    const std::size_t n = m.cols.offsets.size() - 1;
    // Deterministic reduction: the same split tree and order for every run.
    return tbb::parallel_deterministic_reduce(
        tbb::blocked_range<std::size_t>(0, n, 256), EnergyHistogram{},
        [&](const tbb::blocked_range<std::size_t>& range, EnergyHistogram h) {
            cancel.throwIfRequested();
            ColumnScratch& s = scratch.local();
            for (std::size_t j = range.begin(); j != range.end(); ++j)
                transformColumn(m.cols, j, m.layout, m.weights.synthesisNorms, m.columnWeight(j), s.dense, s.charts,
                                [&](std::size_t, float, float e) {
                                    h.energy[energyBin(e)] += e;
                                    h.total += e;
                                });
            stage.advance(range.size());
            return h;
        },
        [](EnergyHistogram a, const EnergyHistogram& b) {
            a.add(b);
            return a;
        });
}

// The lowest energy bin kept so that the kept energy reaches `fraction` of the total.
int thresholdBin(const EnergyHistogram& h, double fraction) {
    if (fraction >= 1.0) return 0;
    double kept = 0.0;
    for (int b = kEnergyBins - 1; b >= 0; --b) {
        kept += h.energy[b];
        if (kept >= fraction * h.total) return b;
    }
    return 0;
}

struct Entry {
    std::uint32_t p;
    float value;
};

// The coefficients of T_k whose energy bin is at least minBin, as a CSR matrix over
// output coefficients p (columns ascending).
SparseMatrix keptCoefficients(const Step2Matrix& m, int minBin, const StageScope& stage, const CancelToken& cancel,
                              tbb::enumerable_thread_specific<ColumnScratch>& scratch) {
    const std::size_t n = m.layout.cells();
    std::vector<std::vector<Entry>> kept(n);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const auto& range) {
        cancel.throwIfRequested();
        ColumnScratch& s = scratch.local();
        for (std::size_t j = range.begin(); j != range.end(); ++j)
            transformColumn(m.cols, j, m.layout, m.weights.synthesisNorms, m.columnWeight(j), s.dense, s.charts,
                            [&](std::size_t p, float c, float e) {
                                if (energyBin(e) >= minBin) kept[j].push_back({std::uint32_t(p), c});
                            });
        stage.advance(range.size());
    });

    SparseMatrix out;
    out.rows = out.cols = std::uint32_t(n);
    out.rowOffsets.assign(n + 1, 0);
    for (const auto& column : kept)
        for (const Entry& e : column) ++out.rowOffsets[e.p + 1];
    for (std::size_t p = 0; p < n; ++p) out.rowOffsets[p + 1] += out.rowOffsets[p];
    out.columns.resize(out.rowOffsets[n]);
    out.values.resize(out.rowOffsets[n]);
    std::vector<std::uint64_t> cursor(out.rowOffsets.begin(), out.rowOffsets.end() - 1);
    for (std::size_t j = 0; j < n; ++j)
        for (const Entry& e : kept[j]) {
            const std::uint64_t at = cursor[e.p]++;
            out.columns[at] = std::uint32_t(j);
            out.values[at] = e.value;
        }
    return out;
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

// Step 2 over all K matrices: one pass to histogram the weighted energies of every k, the
// threshold for `fraction` of their sum, a second pass to keep what reaches it. Each k's
// step-1 rows are transposed to columns once, in the first pass, and released there; its
// columns (no larger: the rows' zero padding is dropped) go after the second.
// *energyKept: the kept fraction.
CompressedTransfer compressSpatialDimension(std::vector<Step1Rows>& step1, const ChartLayout& layout,
                                            const ProfileBasis& basis, double fraction,
                                            ProgressSink* progress, const CancelToken& cancel,
                                            double* energyKept) {
    const std::size_t n = layout.cells();
    const Step2Weights weights = step2Weights(layout, basis);
    tbb::enumerable_thread_specific<ColumnScratch> scratch(
        [&] { return ColumnScratch{std::vector<float>(n, 0.0f), {}}; });
    StageScope stage(progress, "transfer step 2 (CDF 9/7)", 2 * n * step1.size());

    std::vector<Columns> columns(step1.size());
    EnergyHistogram all;
    for (std::size_t k = 0; k < step1.size(); ++k) {
        columns[k] = transpose(step1[k], n);
        step1[k] = Step1Rows{};
        all.add(histogramOfColumns({columns[k], layout, weights, weights.basis[k]}, stage, cancel, scratch));
    }
    const int minBin = thresholdBin(all, fraction);
    double kept = 0.0;
    for (int b = minBin; b < kEnergyBins; ++b) kept += all.energy[b];
    *energyKept = all.total > 0.0 ? kept / all.total : 1.0;

    CompressedTransfer out;
    for (std::size_t k = 0; k < step1.size(); ++k) {
        out.perBasis.push_back(
            keptCoefficients({columns[k], layout, weights, weights.basis[k]}, minBin, stage, cancel, scratch));
        columns[k] = Columns{};
    }
    out.valueSteps = valueSteps(minBin, weights);
    return out;
}

}  // namespace

CompressedTransfer buildTransfer(std::span<const SurfaceSample> samples, const ChartLayout& layout,
                                 double unitsPerMm, const ProfileBasis& basis,
                                 const TransferSettings& settings, ProgressSink* progress,
                                 const CancelToken& cancel, TransferStats* stats) {
    const std::size_t n = samples.size();
    if (n != layout.cells())
        throw Error("transfer: " + std::to_string(n) + " samples do not fill the chart layout of " +
                    std::to_string(layout.cells()) + " cells");
    if (!(settings.keepFraction > 0.0 && settings.keepFraction <= 1.0))
        throw Error("transfer: keep fraction must be in (0, 1], got " + std::to_string(settings.keepFraction));
    if (!(settings.energyFraction > 0.0 && settings.energyFraction <= 1.0))
        throw Error("transfer: energy fraction must be in (0, 1], got " + std::to_string(settings.energyFraction));
    if (basis.K() > 64) throw Error("transfer: at most 64 basis functions are supported");

    const TransferSamples mm = toTransferSamples(samples, unitsPerMm);
    const BasisLookup lookup(basis);
    const double fractionPerRow = settings.keepFraction * double(n);
    const double averagePerRow = std::max(fractionPerRow, double(settings.minPerRow));
    const std::vector<std::uint32_t> perRow = step1Budgets(averagePerRow, n, basis);
    std::vector<Step1Rows> step1 = compressLightDimension(mm, layout, lookup, perRow, progress, cancel);

    double energyKept = 1.0;
    CompressedTransfer out =
        compressSpatialDimension(step1, layout, basis, settings.energyFraction, progress, cancel, &energyKept);
    out.keepFraction = settings.keepFraction;
    out.energyFraction = settings.energyFraction;
    out.selfTerm = SelfTerm::AtRunTime;
    if (stats) {
        const std::uint64_t entryBytes = sizeof(std::uint32_t) + sizeof(float);
        stats->rawBytes = std::uint64_t(n) * n * basis.K() * sizeof(float);
        stats->step1Bytes = 0;
        for (std::uint32_t p : perRow) stats->step1Bytes += std::uint64_t(n) * p * entryBytes;
        stats->step2NonZeros = 0;
        for (const SparseMatrix& m : out.perBasis) stats->step2NonZeros += m.nonZeros();
        stats->step2Bytes = stats->step2NonZeros * entryBytes;
        stats->energyKept = energyKept;
        stats->step1PerRow = 0.0;
        for (std::uint32_t p : perRow) stats->step1PerRow += double(p) / double(perRow.size());
        stats->step1Floor = fractionPerRow < double(settings.minPerRow);
    }
    return out;
}

}  // namespace opal
