#include "bake/farm/farm_task.h"

#include "bake/bake_report.h"
#include "bake/farm/farm_spec.h"
#include "bake/farm/task_file.h"
#include "bake/transfer_stages.h"
#include "schema/error.h"
#include "schema/usd/crash_point.h"

#include <cstdlib>
#include <sstream>

namespace opal {

namespace {

// Everything a task knows about the bake: the spec, the prepared asset and the plan.
struct TaskContext {
    FarmFolder folder;
    FarmSpec spec;
    PreparedBake prepared;
    TransferPlan plan;
    Step2Weights weights;

    explicit TaskContext(const FarmFolder& f)
        : folder(f),
          spec(readFarmSpec(f)),
          prepared(readPreparedBake(f)),
          plan(planTransfer(prepared.asset.samples.size(), prepared.asset.layout, prepared.asset.basis,
                            spec.options.transfer)),
          weights(step2Weights(prepared.asset.layout, prepared.asset.basis)) {}

    std::pair<std::size_t, std::size_t> shard(std::uint32_t i) const { return shardRange(plan.n(), spec.shards, i); }
};

void passCrashPoints(FarmStage stage, std::uint32_t index) {
    const std::string point = "farm:" + std::string(stageName(stage)) + "-" + std::to_string(index);
    crashPoint(point);
    const char* attempt = std::getenv(kFarmAttemptVariable);
    crashPoint(point + ":attempt-" + (attempt ? attempt : "1"));
}

// rows-I.task: section c * K + k holds T_k's entries of rows shard I in column block c,
// as (o, j, value) arrays in row order, zeros dropped.
std::string rowsSection(const Step1Rows& rows, std::size_t firstRow, std::size_t columnBegin, std::size_t columnEnd) {
    std::vector<std::uint32_t> o, j;
    std::vector<float> v;
    forEachRowEntry(rows, firstRow, [&](std::uint32_t row, std::uint32_t column, float value) {
        if (value == 0.0f || column < columnBegin || column >= columnEnd) return;
        o.push_back(row);
        j.push_back(column);
        v.push_back(value);
    });
    SectionWriter w;
    w.array(o);
    w.array(j);
    w.array(v);
    return w.take();
}

void runRows(const TaskContext& c, std::uint32_t index, const CancelToken& cancel) {
    const auto [begin, end] = c.shard(index);
    const TranslucentAsset& asset = c.prepared.asset;
    const std::vector<Step1Rows> rows =
        compressRows(c.plan, toTransferSamples(asset.samples, asset.unitsPerMm), BasisLookup(asset.basis), begin, end,
                     nullptr, cancel);
    std::vector<std::string> sections;
    for (std::uint32_t block = 0; block < c.spec.shards; ++block) {
        const auto [columnBegin, columnEnd] = c.shard(block);
        for (const Step1Rows& k : rows) sections.push_back(rowsSection(k, begin, columnBegin, columnEnd));
    }
    passCrashPoints(FarmStage::Rows, index);
    writeTaskFile(c.folder.output(FarmStage::Rows, index), sections);
}

// T_k's columns of block `index`, from every rows shard in row order.
Step1Columns gatherBlock(const TaskContext& c, std::uint32_t index, std::size_t k) {
    const auto [begin, end] = c.shard(index);
    std::vector<TaskFile> shards;
    for (std::uint32_t s = 0; s < c.spec.shards; ++s) shards.emplace_back(c.folder.output(FarmStage::Rows, s));
    // One shard's section at a time: the block's columns are the only whole thing held.
    return gatherColumns(begin, end, [&](auto&& visit) {
        for (const TaskFile& shard : shards) {
            SectionReader r = shard.section(index * c.plan.K() + k);
            const auto o = r.array<std::uint32_t>("rows");
            const auto j = r.array<std::uint32_t>("columns");
            const auto v = r.array<float>("values");
            r.expectEnd();
            if (j.size() != o.size() || v.size() != o.size())
                r.fail("entries", "differ in count (" + std::to_string(o.size()) + " rows, " +
                                      std::to_string(j.size()) + " columns, " + std::to_string(v.size()) + " values)");
            for (std::size_t e = 0; e < o.size(); ++e) {
                if (o[e] >= c.plan.n() || j[e] < begin || j[e] >= end)
                    r.fail("entry " + std::to_string(e), "is outside the matrix or the block");
                visit(o[e], j[e], v[e]);
            }
        }
    });
}

std::string columnsSection(const Step1Columns& columns) {
    SectionWriter w;
    w.u64(columns.first);
    w.array(columns.offsets);
    w.array(columns.row);
    w.array(columns.value);
    return w.take();
}

Step1Columns readColumns(const TaskContext& c, std::uint32_t index, std::size_t k) {
    SectionReader r = TaskFile(c.folder.output(FarmStage::Columns, index)).section(1 + k);
    Step1Columns columns;
    columns.first = r.u64("first column");
    columns.offsets = r.array<std::uint64_t>("column offsets");
    columns.row = r.array<std::uint32_t>("rows");
    columns.value = r.array<float>("values");
    r.expectEnd();
    const auto [begin, end] = c.shard(index);
    if (columns.first != begin || columns.offsets.size() != end - begin + 1 || columns.offsets.front() != 0 ||
        columns.offsets.back() != columns.row.size() || columns.value.size() != columns.row.size())
        r.fail("columns", "do not describe block " + std::to_string(begin) + ".." + std::to_string(end));
    for (std::size_t j = 0; j + 1 < columns.offsets.size(); ++j)
        if (columns.offsets[j] > columns.offsets[j + 1]) r.fail("column offsets", "decrease");
    for (std::uint32_t o : columns.row)
        if (o >= c.plan.n()) r.fail("rows", "name an output past the matrix");
    return columns;
}

void runColumns(const TaskContext& c, std::uint32_t index, const CancelToken& cancel) {
    const StageScope stage(nullptr, "", 0);
    EnergyHistogram histogram;
    std::vector<std::string> sections(1);
    for (std::size_t k = 0; k < c.plan.K(); ++k) {
        const Step1Columns columns = gatherBlock(c, index, k);
        histogram.add(histogramOfColumns(columns, c.plan.layout, c.weights, k, stage, cancel));
        sections.push_back(columnsSection(columns));
    }
    SectionWriter w;
    w.array(histogram.words());
    sections[0] = w.take();
    passCrashPoints(FarmStage::Columns, index);
    writeTaskFile(c.folder.output(FarmStage::Columns, index), sections);
}

// The sum of every columns task's histogram: the same whatever the shards (exact sums).
EnergyHistogram allEnergies(const TaskContext& c) {
    EnergyHistogram all;
    for (std::uint32_t s = 0; s < c.spec.shards; ++s) {
        SectionReader r = TaskFile(c.folder.output(FarmStage::Columns, s)).section(0);
        all.add(EnergyHistogram::fromWords(r.array<std::uint64_t>("energy histogram")));
        r.expectEnd();
    }
    return all;
}

void runKeep(const TaskContext& c, std::uint32_t index, const CancelToken& cancel) {
    const int minBin = allEnergies(c).thresholdBin(c.plan.settings.energyFraction);
    const StageScope stage(nullptr, "", 0);
    std::vector<std::string> sections;
    for (std::size_t k = 0; k < c.plan.K(); ++k) {
        const KeptColumns kept =
            keptColumns(readColumns(c, index, k), c.plan.layout, c.weights, k, minBin, stage, cancel);
        std::vector<std::uint32_t> counts, p;
        std::vector<float> values;
        for (const auto& column : kept.columns) {
            counts.push_back(std::uint32_t(column.size()));
            for (const KeptEntry& e : column) {
                p.push_back(e.p);
                values.push_back(e.value);
            }
        }
        SectionWriter w;
        w.u64(kept.first);
        w.array(counts);
        w.array(p);
        w.array(values);
        sections.push_back(w.take());
    }
    passCrashPoints(FarmStage::Keep, index);
    writeTaskFile(c.folder.output(FarmStage::Keep, index), sections);
}

KeptColumns readKept(const TaskContext& c, std::uint32_t index, std::size_t k) {
    SectionReader r = TaskFile(c.folder.output(FarmStage::Keep, index)).section(k);
    KeptColumns kept;
    kept.first = r.u64("first column");
    const auto counts = r.array<std::uint32_t>("counts");
    const auto p = r.array<std::uint32_t>("outputs");
    const auto values = r.array<float>("values");
    r.expectEnd();
    const auto [begin, end] = c.shard(index);
    if (kept.first != begin || counts.size() != end - begin || values.size() != p.size())
        r.fail("kept columns", "do not describe block " + std::to_string(begin) + ".." + std::to_string(end));
    std::size_t at = 0;
    kept.columns.resize(counts.size());
    for (std::size_t j = 0; j < counts.size(); ++j) {
        if (counts[j] > p.size() - at) r.fail("counts", "exceed the " + std::to_string(p.size()) + " entries");
        for (std::uint32_t e = 0; e < counts[j]; ++e, ++at) kept.columns[j].push_back({p[at], values[at]});
    }
    if (at != p.size()) r.fail("counts", "leave entries over");
    return kept;
}

std::string runMerge(const TaskContext& c, const CancelToken& cancel) {
    const EnergyHistogram all = allEnergies(c);
    const int minBin = all.thresholdBin(c.plan.settings.energyFraction);
    TranslucentAsset asset = c.prepared.asset;
    asset.transfer = transferShell(c.plan, minBin, c.weights);
    for (std::size_t k = 0; k < c.plan.K(); ++k) {
        KeptMatrixAssembler matrix(c.plan.n());
        for (std::uint32_t s = 0; s < c.spec.shards; ++s) matrix.count(readKept(c, s, k));
        for (std::uint32_t s = 0; s < c.spec.shards; ++s) matrix.fill(readKept(c, s, k));
        asset.transfer.perBasis.push_back(matrix.take());
    }
    BakeReport report;
    report.warnings = c.prepared.warnings;
    report.transfer = transferStats(c.plan, asset.transfer, all.fractionFrom(minBin));
    finishBake(c.spec.options, asset, nullptr, cancel, &report);
    passCrashPoints(FarmStage::Merge, 0);
    writeBakedAsset(std::filesystem::path(c.spec.stem), asset, &report);
    std::error_code ignored;  // the asset is written: the intermediates are of no more use
    std::filesystem::remove_all(c.folder.path(), ignored);
    std::ostringstream s;
    for (const std::string& w : report.warnings) s << "opal-bake: warning: " << w << '\n';
    s << formatBakeSummary(c.spec.stem, report);
    return s.str();
}

}  // namespace

FarmTaskResult runFarmTask(const FarmFolder& folder, FarmStage stage, std::uint32_t index, const CancelToken& cancel) {
    FarmTaskResult result;
    try {
        if (index >= taskCount(stage, readFarmSpec(folder).shards))
            throw Error("there is no such task (the bake has " +
                        std::to_string(taskCount(stage, readFarmSpec(folder).shards)) + " " +
                        std::string(stageName(stage)) + " tasks)");
        if (stage != FarmStage::Merge && isCompleteTaskFile(folder.output(stage, index))) {
            result.ranAlready = true;
            return result;
        }
        if (stage == FarmStage::Prepare) {
            const FarmSpec spec = readFarmSpec(folder);
            BakeReport report;
            PreparedBake prepared{prepareBake(spec.options, nullptr, cancel, &report), {}};
            prepared.warnings = report.warnings;
            passCrashPoints(stage, index);
            writePreparedBake(folder, prepared);
            return result;
        }
        const TaskContext context(folder);
        switch (stage) {
        case FarmStage::Rows: runRows(context, index, cancel); break;
        case FarmStage::Columns: runColumns(context, index, cancel); break;
        case FarmStage::Keep: runKeep(context, index, cancel); break;
        case FarmStage::Merge: result.summary = runMerge(context, cancel); break;
        case FarmStage::Prepare: break;
        }
        return result;
    } catch (const Cancelled&) {
        throw;
    } catch (const std::exception& e) {
        throw Error("farm task " + taskName(stage, index) + " (" + folder.path().string() + "): " + e.what());
    }
}

}  // namespace opal
