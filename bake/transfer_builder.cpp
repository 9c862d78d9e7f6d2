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
#include <numbers>
#include <vector>

namespace opal {

namespace {

// Step 1's importance of each Haar coefficient of a chart: the number of cells its basis
// function covers (Mallat layout, haar.h): the whole chart for the scaling function,
// (2 size / s)^2 for a detail of the active s x s block (max(u, v) in [s/2, s)).
// A row coefficient c_j meets the light's coefficient E^_j in the product, and for
// irradiance that is smooth at the scale of a basis function |E^_j| grows with its support,
// so rows keep the largest |c_j| area_j rather than the largest |c_j|. Measured on a
// 4,096-sample candle at keep 1% under a point light, step-1 error: |c_j| 17%,
// |c_j| sqrt(area_j) 4.3%, |c_j| area_j 3.5%, |c_j| area_j^2 12%.
std::vector<float> haarImportance(std::uint32_t size) {
    std::vector<float> area(std::size_t(size) * size);
    for (std::uint32_t u = 0; u < size; ++u)
        for (std::uint32_t v = 0; v < size; ++v) {
            const std::uint32_t m = std::max(u, v);
            const double side = m == 0 ? double(size) : 2.0 * size / double(std::bit_floor(m) * 2);
            area[std::size_t(u) * size + v] = float(side * side);
        }
    return area;
}

// The retained Haar coefficients of step 1: the same count for every row.
struct Step1Rows {
    std::uint32_t perRow = 0;
    std::vector<std::uint32_t> column;  // N x perRow, ascending within a row
    std::vector<float> value;
};

// The samples in mm (transfer_row.h) and selfTerm[o * K + k] = T_k[o][o], the profile
// integrated over the sample's own disk.
struct SamplesMm {
    TransferSamples samples;
    std::vector<float> selfTerm;
};

SamplesMm toMillimetres(std::span<const SurfaceSample> samples, double unitsPerMm, const ProfileBasis& basis) {
    SamplesMm mm{toTransferSamples(samples, unitsPerMm), {}};
    mm.selfTerm = transferSelfTerms(mm.samples.area, basis);
    return mm;
}

std::vector<Step1Rows> compressLightDimension(const SamplesMm& mm, const ChartLayout& layout,
                                              const BasisLookup& lookup, std::uint32_t perRow,
                                              ProgressSink* progress, const CancelToken& cancel) {
    const std::size_t n = mm.samples.size();
    const int K = lookup.K();
    std::vector<Step1Rows> rows(K);
    for (Step1Rows& r : rows) {
        r.perRow = perRow;
        r.column.resize(n * perRow);
        r.value.resize(n * perRow);
    }
    StageScope stage(progress, "transfer step 1 (Haar)", n);
    const std::size_t stride = transferRowStride(n);  // rows of K apart in cache sets
    const std::size_t rowsSize = std::size_t(K - 1) * stride + n;
    tbb::enumerable_thread_specific<std::vector<float>> scratch([&] { return std::vector<float>(rowsSize + n); });
    const std::size_t cellsPerChart = layout.cellsPerChart();
    const std::vector<float> importance = haarImportance(layout.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 8), [&](const auto& range) {
        cancel.throwIfRequested();
        std::vector<float>& buf = scratch.local();
        const std::span<float> all(buf.data(), rowsSize);
        const std::span<float> weighted(buf.data() + rowsSize, n);
        for (std::size_t o = range.begin(); o != range.end(); ++o) {
            transferRow(o, mm.samples, lookup, all, stride);
            for (int k = 0; k < K; ++k) {
                const std::span<float> row(buf.data() + std::size_t(k) * stride, n);
                row[o] = mm.selfTerm[o * std::size_t(K) + std::size_t(k)];
                haarForwardCharts(row, layout);
                for (std::size_t c = 0; c < n; c += cellsPerChart)
                    for (std::size_t q = 0; q < cellsPerChart; ++q) weighted[c + q] = row[c + q] * importance[q];
                const SparseVector kept = keepLargest(weighted, perRow);
                std::copy(kept.indices.begin(), kept.indices.end(), rows[k].column.begin() + o * perRow);
                for (std::size_t e = 0; e < kept.size(); ++e)
                    rows[k].value[o * perRow + e] = row[kept.indices[e]];
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

// Energies are binned by the top bits of their float representation: for positive
// floats the bit pattern is monotonic, so bins are ordered (1/8 octave each).
constexpr int kEnergyBins = 1 << 12;
int energyBin(float e) { return int(std::bit_cast<std::uint32_t>(e) >> 19); }

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
// the charts the column touches; energy = c^2 |synthesis function|^2 (9/7 is biorthogonal).
template <typename Visit>
void transformColumn(const Columns& cols, std::size_t j, const ChartLayout& layout,
                     std::span<const float> normsSquared, std::vector<float>& dense,
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
            if (c != 0.0f) visit(chart * cellsPerChart + q, c, c * c * normsSquared[q]);
            grid[q] = 0.0f;
        }
    }
}

struct ColumnScratch {
    std::vector<float> dense;
    std::vector<std::uint32_t> charts;
};

EnergyHistogram histogramOfColumns(const Columns& cols, const ChartLayout& layout,
                                   std::span<const float> norms, const StageScope& stage,
                                   const CancelToken& cancel,
                                   tbb::enumerable_thread_specific<ColumnScratch>& scratch) {
    const std::size_t n = cols.offsets.size() - 1;
    // Deterministic reduction: the same split tree and order for every run.
    return tbb::parallel_deterministic_reduce(
        tbb::blocked_range<std::size_t>(0, n, 256), EnergyHistogram{},
        [&](const tbb::blocked_range<std::size_t>& range, EnergyHistogram h) {
            cancel.throwIfRequested();
            ColumnScratch& s = scratch.local();
            for (std::size_t j = range.begin(); j != range.end(); ++j)
                transformColumn(cols, j, layout, norms, s.dense, s.charts, [&](std::size_t, float, float e) {
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

SparseMatrix compressSpatialDimension(const Step1Rows& rows, const ChartLayout& layout,
                                      double fraction, const StageScope& stage,
                                      const CancelToken& cancel, double* keptEnergy,
                                      double* totalEnergy) {
    const std::size_t n = layout.cells();
    const Columns cols = transpose(rows, n);
    const std::vector<float> norms = cdf97SynthesisNormsSquared(layout.size());
    tbb::enumerable_thread_specific<ColumnScratch> scratch(
        [&] { return ColumnScratch{std::vector<float>(n, 0.0f), {}}; });

    const EnergyHistogram h = histogramOfColumns(cols, layout, norms, stage, cancel, scratch);
    const int minBin = thresholdBin(h, fraction);

    std::vector<std::vector<Entry>> kept(n);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const auto& range) {
        cancel.throwIfRequested();
        ColumnScratch& s = scratch.local();
        for (std::size_t j = range.begin(); j != range.end(); ++j)
            transformColumn(cols, j, layout, norms, s.dense, s.charts, [&](std::size_t p, float c, float e) {
                if (energyBin(e) >= minBin) kept[j].push_back({std::uint32_t(p), c});
            });
        stage.advance(range.size());
    });

    double keptSum = 0.0;
    for (int b = minBin; b < kEnergyBins; ++b) keptSum += h.energy[b];
    *keptEnergy += keptSum;
    *totalEnergy += h.total;

    // Regroup by output coefficient p (CSR rows); columns come out ascending.
    SparseMatrix m;
    m.rows = m.cols = std::uint32_t(n);
    m.rowOffsets.assign(n + 1, 0);
    for (const auto& column : kept)
        for (const Entry& e : column) ++m.rowOffsets[e.p + 1];
    for (std::size_t p = 0; p < n; ++p) m.rowOffsets[p + 1] += m.rowOffsets[p];
    m.columns.resize(m.rowOffsets[n]);
    m.values.resize(m.rowOffsets[n]);
    std::vector<std::uint64_t> cursor(m.rowOffsets.begin(), m.rowOffsets.end() - 1);
    for (std::size_t j = 0; j < n; ++j)
        for (const Entry& e : kept[j]) {
            const std::uint64_t at = cursor[e.p]++;
            m.columns[at] = std::uint32_t(j);
            m.values[at] = e.value;
        }
    return m;
}

}  // namespace

std::vector<float> transferSelfTerms(std::span<const float> areasMm2, const ProfileBasis& basis) {
    const std::size_t K = std::size_t(basis.K());
    std::vector<float> terms(areasMm2.size() * K);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, areasMm2.size(), 1024), [&](const auto& range) {
        std::vector<double> integral(K);
        for (std::size_t o = range.begin(); o != range.end(); ++o) {
            basis.diskIntegrals(std::sqrt(double(areasMm2[o]) / std::numbers::pi), integral);
            for (std::size_t k = 0; k < K; ++k) terms[o * K + k] = float(integral[k]);
        }
    });
    return terms;
}

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

    const SamplesMm mm = toMillimetres(samples, unitsPerMm, basis);
    const BasisLookup lookup(basis);
    const auto perRow = std::uint32_t(std::clamp<double>(std::ceil(settings.keepFraction * double(n)), 1.0, double(n)));
    std::vector<Step1Rows> step1 = compressLightDimension(mm, layout, lookup, perRow, progress, cancel);

    CompressedTransfer out;
    out.keepFraction = settings.keepFraction;
    out.energyFraction = settings.energyFraction;
    double keptEnergy = 0.0, totalEnergy = 0.0;
    StageScope stage(progress, "transfer step 2 (CDF 9/7)", 2 * n * step1.size());
    for (Step1Rows& rows : step1) {
        out.perBasis.push_back(compressSpatialDimension(rows, layout, settings.energyFraction, stage, cancel,
                                                        &keptEnergy, &totalEnergy));
        rows = Step1Rows{};  // release step-1 memory as soon as a k is done
    }
    if (stats) {
        const std::uint64_t entryBytes = sizeof(std::uint32_t) + sizeof(float);
        stats->rawBytes = std::uint64_t(n) * n * basis.K() * sizeof(float);
        stats->step1Bytes = std::uint64_t(n) * perRow * basis.K() * entryBytes;
        stats->step2NonZeros = 0;
        for (const SparseMatrix& m : out.perBasis) stats->step2NonZeros += m.nonZeros();
        stats->step2Bytes = stats->step2NonZeros * entryBytes;
        stats->energyKept = totalEnergy > 0 ? keptEnergy / totalEnergy : 1.0;
    }
    return out;
}

}  // namespace opal
