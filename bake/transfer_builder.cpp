#include "bake/transfer_builder.h"

#include "bake/transfer_stages.h"

#include <vector>

namespace opal {

CompressedTransfer buildTransfer(std::span<const SurfaceSample> samples, const ChartLayout& layout,
                                 double unitsPerMm, const ProfileBasis& basis,
                                 const TransferSettings& settings, ProgressSink* progress,
                                 const CancelToken& cancel, TransferStats* stats) {
    const TransferPlan plan = planTransfer(samples.size(), layout, basis, settings);
    const std::size_t n = plan.n();
    const TransferSamples mm = toTransferSamples(samples, unitsPerMm);
    std::vector<Step1Rows> rows = compressRows(plan, mm, BasisLookup(basis), 0, n, progress, cancel);

    // Step 2 over all K matrices: one pass to histogram the weighted energies of every k,
    // the threshold for the energy fraction of their sum, a second pass to keep what
    // reaches it. Each k's rows are regrouped by column once, in the first pass, and
    // released there; its columns (no larger: the rows' zero padding is dropped) go after
    // the second.
    const Step2Weights weights = step2Weights(layout, basis);
    StageScope stage(progress, "transfer step 2 (CDF 9/7)", 2 * n * plan.K());
    std::vector<Step1Columns> columns(plan.K());
    EnergyHistogram all;
    std::vector<float> harmonics = gatherHarmonics(rows, 0, n);
    for (std::size_t k = 0; k < plan.K(); ++k) {
        columns[k] = gatherColumns(0, n, [&](auto&& visit) { forEachRowEntry(rows[k], 0, visit); });
        rows[k] = Step1Rows{};
        all.add(histogramOfColumns(columns[k], layout, weights, k, stage, cancel));
    }
    const int minBin = all.thresholdBin(settings.energyFraction);

    CompressedTransfer out = transferShell(plan, minBin, weights);
    out.harmonics = std::move(harmonics);
    out.harmonicSet = mm.harmonicSet;
    for (std::size_t k = 0; k < plan.K(); ++k) {
        const KeptColumns kept = keptColumns(columns[k], layout, weights, k, minBin, stage, cancel);
        columns[k] = Step1Columns{};
        KeptMatrixAssembler matrix(n);
        matrix.count(kept);
        matrix.fill(kept);
        out.perBasis.push_back(matrix.take());
    }
    if (stats) *stats = transferStats(plan, out, all.fractionFrom(minBin));
    return out;
}

}  // namespace opal
