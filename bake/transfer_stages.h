// The transfer's two compression steps (transfer_builder.h) cut into pieces that can run
// on any part of the matrix: step 1 for a range of output rows, the rows' coefficients
// regrouped by a range of columns, step 2's energy histogram and kept coefficients for a
// range of columns, and the kept columns assembled into the final matrices. A plain bake
// (buildTransfer) runs them over the whole matrix in one process; a farm bake
// (bake/farm/) runs them as tasks over shards. Every piece is a function of its own rows
// or columns alone, and the one reduction between them, the energy histogram, is exact
// (energy_histogram.h), so any split gives the same bytes.
#pragma once

#include "bake/energy_histogram.h"
#include "bake/progress.h"
#include "bake/transfer_builder.h"
#include "bake/transfer_row.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace opal {

// What every piece needs besides its rows or columns: derived from the samples' count,
// the layout, the basis and the settings alone.
struct TransferPlan {
    ChartLayout layout;
    std::vector<std::uint32_t> perRow;  // step 1: Haar coefficients kept per row, per k
    double fractionPerRow = 0.0;        // keepFraction x N, before the minPerRow floor
    TransferSettings settings;

    std::size_t n() const { return layout.cells(); }
    std::size_t K() const { return perRow.size(); }
};

// Checks the settings (opal::Error naming the bad one) and derives the plan.
TransferPlan planTransfer(std::size_t sampleCount, const ChartLayout& layout, const ProfileBasis& basis,
                          const TransferSettings& settings);

// Step 1's retained Haar coefficients of one T_k for consecutive output rows: perRow
// entries a row, columns ascending, rows with fewer nonzero coefficients padded with zero
// values at column 0.
struct Step1Rows {
    std::uint32_t perRow = 0;
    std::vector<std::uint32_t> column;  // rows x perRow
    std::vector<float> value;
    std::vector<float> harmonics;  // rows x Q: the row's T_k f_q, before step 1 (Q = the set's count)
};

// Step 1 for output rows [begin, end), one Step1Rows per k.
std::vector<Step1Rows> compressRows(const TransferPlan& plan, const TransferSamples& samples,
                                    const BasisLookup& lookup, std::size_t begin, std::size_t end,
                                    ProgressSink* progress, const CancelToken& cancel);

// Rows [begin, end) of CompressedTransfer::harmonics, [((o - begin) K + k) Q + q], from
// each k's Step1Rows of those rows.
std::vector<float> gatherHarmonics(const std::vector<Step1Rows>& rows, std::size_t begin, std::size_t end);

// Columns [first, first + count()) of one sparse N x N matrix, column by column: column
// first + c holds the entries offsets[c] .. offsets[c + 1] - 1 of row and value, rows
// ascending.
struct ColumnBlock {
    std::size_t first = 0;
    std::vector<std::uint64_t> offsets{0};  // count() + 1
    std::vector<std::uint32_t> row;
    std::vector<float> value;

    std::size_t count() const { return offsets.empty() ? 0 : offsets.size() - 1; }
};

// Step 1's coefficients of T_k regrouped by column: rows are output samples o; zero values
// (the rows' padding) are dropped.
using Step1Columns = ColumnBlock;

// Regroups entries by column for columns [begin, end). forEachEntry(visit) must call
// visit(o, j, value) for every entry, o ascending, the same entries each time: it is
// called twice (a count, then a fill). Entries outside the columns or with a zero value
// are skipped.
template <class ForEachEntry>
Step1Columns gatherColumns(std::size_t begin, std::size_t end, ForEachEntry&& forEachEntry) {
    Step1Columns c;
    c.first = begin;
    c.offsets.assign(end - begin + 1, 0);
    const auto inside = [&](std::uint32_t j, float v) { return v != 0.0f && j >= begin && j < end; };
    forEachEntry([&](std::uint32_t, std::uint32_t j, float v) {
        if (inside(j, v)) ++c.offsets[j - begin + 1];
    });
    for (std::size_t j = 0; j < end - begin; ++j) c.offsets[j + 1] += c.offsets[j];
    c.row.resize(c.offsets.back());
    c.value.resize(c.offsets.back());
    std::vector<std::uint64_t> cursor(c.offsets.begin(), c.offsets.end() - 1);
    forEachEntry([&](std::uint32_t o, std::uint32_t j, float v) {
        if (!inside(j, v)) return;
        const std::uint64_t at = cursor[j - begin]++;
        c.row[at] = o;
        c.value[at] = v;
    });
    return c;
}

// Calls visit(o, j, value) for every entry of rows, which hold rows firstRow, firstRow + 1, ...
template <class Visit>
void forEachRowEntry(const Step1Rows& rows, std::size_t firstRow, Visit&& visit) {
    if (rows.perRow == 0) return;
    const std::size_t count = rows.column.size() / rows.perRow;
    for (std::size_t r = 0; r < count; ++r)
        for (std::uint32_t e = 0; e < rows.perRow; ++e) {
            const std::size_t at = r * rows.perRow + e;
            visit(std::uint32_t(firstRow + r), rows.column[at], rows.value[at]);
        }
}

// Step 2 (transfer_builder.h): per chart position, the 9/7 synthesis norms g_p and the
// Haar support areas a_j, and per k lambda_k / lambda_1.
struct Step2Weights {
    std::vector<float> synthesisNorms;
    std::vector<float> columnArea;
    std::vector<double> basis;
};

Step2Weights step2Weights(const ChartLayout& layout, const ProfileBasis& basis);

// Step 2's first pass over T_k's columns: the histogram of their weighted 9/7 energies.
// `stage` advances by one a column.
EnergyHistogram histogramOfColumns(const Step1Columns& columns, const ChartLayout& layout,
                                   const Step2Weights& weights, std::size_t k, const StageScope& stage,
                                   const CancelToken& cancel);

// Step 2's second pass: per column, the coefficients whose energy bin is at least minBin;
// rows are output 9/7 positions p.
using KeptColumns = ColumnBlock;

KeptColumns keptColumns(const Step1Columns& columns, const ChartLayout& layout, const Step2Weights& weights,
                        std::size_t k, int minBin, const StageScope& stage, const CancelToken& cancel);

// Builds T_k's CSR matrix (rows: output coefficients p, columns ascending) from its kept
// columns, given in blocks of consecutive columns from 0: every block once to count(),
// then every block again, in the same order, to fill().
class KeptMatrixAssembler {
public:
    explicit KeptMatrixAssembler(std::size_t n);
    void count(const KeptColumns& block);
    void fill(const KeptColumns& block);
    SparseMatrix take();  // after the fills; checks every counted entry was filled

private:
    SparseMatrix matrix_;
    std::vector<std::uint64_t> cursor_;
    bool filling_ = false;
};

// The grid kept values are stored on (schema/asset/transfer_value_grid.h), per k.
std::vector<double> valueSteps(int minBin, const Step2Weights& weights);

// The finished transfer's fields besides its matrices, and the statistics of the bake.
CompressedTransfer transferShell(const TransferPlan& plan, int minBin, const Step2Weights& weights);
TransferStats transferStats(const TransferPlan& plan, const CompressedTransfer& transfer, double energyKept);

}  // namespace opal
