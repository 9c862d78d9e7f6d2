#include "bake/farm/farm_task.h"

#include "bake/bake_report.h"
#include "bake/farm/farm_spec.h"
#include "bake/farm/task_file.h"
#include "bake/farm/task_stats.h"
#include "bake/transfer_stages.h"
#include "schema/error.h"
#include "schema/usd/crash_point.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
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

// The column block of each column.
std::vector<std::uint32_t> columnBlocks(const TaskContext& c) {
    std::vector<std::uint32_t> blockOf(c.plan.n());
    for (std::uint32_t b = 0; b < c.spec.shards; ++b) {
        const auto [columnBegin, columnEnd] = c.shard(b);
        std::fill(blockOf.begin() + std::ptrdiff_t(columnBegin), blockOf.begin() + std::ptrdiff_t(columnEnd), b);
    }
    return blockOf;
}

// rows-I.task: section k * N + c holds T_k's entries of rows shard I in column block c,
// zeros dropped, row by row: how many each row of the shard has, then their columns and
// values (each row's ascending):
//   u64 rows | count[rows] (u32) | u64 n | j[n] (u32) | u64 n | value[n] (f32)
// 8 bytes an entry (a row index per entry made it 12, and the rows files are what the
// bake writes most: 7.9 GB at 65,536 samples).
// One k's N sections are made together, in two passes over its rows (count each block's
// entries, then place them) rather than four passes per block: the rows task's memory
// beyond its rows is one k's entries, in `sections`, whose strings are reused from k to
// k: their memory is touched once per task, not once per k (fresh pages cost a page
// fault each).
void rowsSections(const Step1Rows& rows, std::size_t firstRow, std::uint64_t rowCount,
                  const std::vector<std::uint32_t>& blockOf, std::uint32_t blocks, std::vector<std::string>& sections) {
    std::vector<std::uint64_t> total(blocks, 0);
    std::vector<std::uint32_t> perRow(std::size_t(blocks) * rowCount, 0);  // [block][row]
    forEachRowEntry(rows, firstRow, [&](std::uint32_t o, std::uint32_t j, float v) {
        if (v == 0.0f) return;
        ++total[blockOf[j]];
        ++perRow[blockOf[j] * rowCount + (o - firstRow)];
    });
    sections.resize(blocks);
    struct Cursor {
        char *j, *v;
    };
    std::vector<Cursor> at(blocks);
    for (std::uint32_t b = 0; b < blocks; ++b) {
        const std::uint64_t n = total[b];
        const std::uint64_t countsBytes = 8 + 4 * rowCount;
        sections[b].clear();
        sections[b].resize(countsBytes + 16 + n * 8);
        char* const base = sections[b].data();
        std::memcpy(base, &rowCount, 8);
        std::memcpy(base + 8, perRow.data() + b * rowCount, 4 * rowCount);
        std::memcpy(base + countsBytes, &n, 8);
        std::memcpy(base + countsBytes + 8 + 4 * n, &n, 8);
        at[b] = {base + countsBytes + 8, base + countsBytes + 16 + 4 * n};
    }
    forEachRowEntry(rows, firstRow, [&](std::uint32_t, std::uint32_t j, float v) {
        if (v == 0.0f) return;
        Cursor& cursor = at[blockOf[j]];
        std::memcpy(cursor.j, &j, 4);
        std::memcpy(cursor.v, &v, 4);
        cursor.j += 4;
        cursor.v += 4;
    });
}

void runRows(const TaskContext& c, std::uint32_t index, const CancelToken& cancel) {
    const auto [begin, end] = c.shard(index);
    const TranslucentAsset& asset = c.prepared.asset;
    std::vector<Step1Rows> rows =
        compressRows(c.plan, toTransferSamples(asset.samples, asset.unitsPerMm), BasisLookup(asset.basis), begin, end,
                     nullptr, cancel);
    // Section by section, each k's rows released once written: the rows are the peak. The
    // last section: the rows' harmonic transfer, which the merge joins.
    TaskFileWriter file(c.folder.output(FarmStage::Rows, index), rows.size() * c.spec.shards + 1);
    const std::vector<std::uint32_t> blockOf = columnBlocks(c);
    SectionWriter harmonics;
    harmonics.array(gatherHarmonics(rows, begin, end));
    std::vector<std::string> sections;
    for (Step1Rows& k : rows) {
        rowsSections(k, begin, end - begin, blockOf, c.spec.shards, sections);
        for (const std::string& section : sections) file.add(section);
        k = Step1Rows{};
    }
    file.add(harmonics.take());
    passCrashPoints(FarmStage::Rows, index);
    file.commit();
}

// Every task's file of `stage` (rows or keep: one per shard), mapped once for all k.
std::vector<TaskFile> stageFiles(const TaskContext& c, FarmStage stage) {
    std::vector<TaskFile> files;
    for (std::uint32_t s = 0; s < c.spec.shards; ++s) files.emplace_back(c.folder.output(stage, s));
    return files;
}

// T_k's columns of block `index`, from every rows shard in row order.
Step1Columns gatherBlock(const TaskContext& c, const std::vector<TaskFile>& rows, std::uint32_t index,
                         std::size_t k) {
    const auto [begin, end] = c.shard(index);
    // T_k's entries of the block from every rows shard, visited in place in the mapped
    // files (the block's columns are what the task holds).
    struct Entries {
        std::uint32_t firstRow;
        SectionArray<std::uint32_t> count, j;
        SectionArray<float> v;
    };
    std::vector<Entries> pieces;
    for (std::uint32_t s = 0; s < c.spec.shards; ++s) {
        SectionReader r = rows[s].section(k * c.spec.shards + index);
        const auto [rowBegin, rowEnd] = c.shard(s);
        const Entries& e = pieces.emplace_back(Entries{std::uint32_t(rowBegin), r.view<std::uint32_t>("row counts"),
                                                       r.view<std::uint32_t>("columns"), r.view<float>("values")});
        r.expectEnd();
        if (e.count.size() != rowEnd - rowBegin)
            r.fail("row counts", "hold " + std::to_string(e.count.size()) + " rows, the shard has " +
                                     std::to_string(rowEnd - rowBegin));
        std::uint64_t entries = 0;
        for (std::size_t i = 0; i < e.count.size(); ++i) entries += e.count[i];
        if (e.j.size() != entries || e.v.size() != entries)
            r.fail("entries", "differ in count (" + std::to_string(entries) + " by the rows, " +
                                  std::to_string(e.j.size()) + " columns, " + std::to_string(e.v.size()) + " values)");
        for (std::size_t i = 0; i < e.j.size(); ++i)
            if (e.j[i] < begin || e.j[i] >= end) r.fail("entry " + std::to_string(i), "is outside the block");
    }
    return gatherColumns(begin, end, [&](auto&& visit) {
        for (const Entries& e : pieces)
            for (std::size_t r = 0, i = 0; r < e.count.size(); ++r)
                for (const std::size_t rowEnd = i + e.count[r]; i < rowEnd; ++i)
                    visit(std::uint32_t(e.firstRow + r), e.j[i], e.v[i]);
    });
}

void runColumns(const TaskContext& c, std::uint32_t index, const CancelToken& cancel) {
    const StageScope stage(nullptr, "", 0);
    EnergyHistogram histogram;
    // One section: the histogram. The block's columns are not written: the keep task
    // gathers them again from the rows shards, which costs less than writing and reading
    // them back (the whole step-1 matrix, once more, across the columns files).
    const std::vector<TaskFile> rows = stageFiles(c, FarmStage::Rows);
    for (std::size_t k = 0; k < c.plan.K(); ++k)
        histogram.add(histogramOfColumns(gatherBlock(c, rows, index, k), c.plan.layout, c.weights, k, stage, cancel));
    TaskFileWriter file(c.folder.output(FarmStage::Columns, index), 1);
    SectionWriter w;
    w.array(histogram.words());
    file.add(w.take());
    passCrashPoints(FarmStage::Columns, index);
    file.commit();
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
    TaskFileWriter file(c.folder.output(FarmStage::Keep, index), c.plan.K());
    const std::vector<TaskFile> rows = stageFiles(c, FarmStage::Rows);
    for (std::size_t k = 0; k < c.plan.K(); ++k) {
        const KeptColumns kept =
            keptColumns(gatherBlock(c, rows, index, k), c.plan.layout, c.weights, k, minBin, stage, cancel);
        std::vector<std::uint32_t> counts(kept.count());
        for (std::size_t j = 0; j < counts.size(); ++j) counts[j] = std::uint32_t(kept.offsets[j + 1] - kept.offsets[j]);
        SectionWriter w;
        w.reserve(4 * sizeof(std::uint64_t) + counts.size() * 4 + kept.row.size() * 8);
        w.u64(kept.first);
        w.array(counts);
        w.array(kept.row);
        w.array(kept.value);
        file.add(w.take());
    }
    passCrashPoints(FarmStage::Keep, index);
    file.commit();
}

KeptColumns readKept(const TaskContext& c, const TaskFile& file, std::uint32_t index, std::size_t k) {
    SectionReader r = file.section(k);
    KeptColumns kept;
    kept.first = r.u64("first column");
    const auto counts = r.array<std::uint32_t>("counts");
    auto p = r.array<std::uint32_t>("outputs");
    auto values = r.array<float>("values");
    r.expectEnd();
    const auto [begin, end] = c.shard(index);
    if (kept.first != begin || counts.size() != end - begin || values.size() != p.size())
        r.fail("kept columns", "do not describe block " + std::to_string(begin) + ".." + std::to_string(end));
    kept.offsets.resize(counts.size() + 1);
    for (std::size_t j = 0; j < counts.size(); ++j) {
        if (counts[j] > p.size() - kept.offsets[j])
            r.fail("counts", "exceed the " + std::to_string(p.size()) + " entries");
        kept.offsets[j + 1] = kept.offsets[j] + counts[j];
    }
    if (kept.offsets.back() != p.size()) r.fail("counts", "leave entries over");
    kept.row = std::move(p);
    kept.value = std::move(values);
    return kept;
}

// Where the submitting opal-bake asked for the JSON report, if it did.
std::optional<std::filesystem::path> requestedReport(const FarmFolder& folder) {
    std::ifstream in(folder.reportRequest());
    std::string path;
    if (!in || !std::getline(in, path) || path.empty()) return std::nullopt;
    return std::filesystem::path(path);
}

// The farm's part of the report: every stage's tasks, the merge (this process) last.
void addFarmStats(const TaskContext& c, double mergeSeconds, BakeReport& report) {
    report.farmShards = c.spec.shards;
    report.farmStages = gatherStageTasks(c.folder, c.spec.shards, report.warnings);
    report.farmStages.push_back({"merge", 1, 1, mergeSeconds, mergeSeconds, peakRssBytes()});
    report.peakRssBytes = 0;
    for (const StageTasks& s : report.farmStages) report.peakRssBytes = std::max(report.peakRssBytes, s.peakRssBytes);
}

// CompressedTransfer::harmonics from every rows shard's last section, in row order.
std::vector<float> joinHarmonics(const TaskContext& c, std::size_t Q) {
    const std::size_t K = c.plan.K();
    std::vector<float> all(c.plan.n() * K * Q);
    for (std::uint32_t s = 0; s < c.spec.shards; ++s) {
        const auto [begin, end] = c.shard(s);
        SectionReader r = TaskFile(c.folder.output(FarmStage::Rows, s)).section(K * c.spec.shards);
        const auto values = r.array<float>("harmonic transfer");
        r.expectEnd();
        if (values.size() != (end - begin) * K * Q)
            r.fail("harmonic transfer", "holds " + std::to_string(values.size()) + " values, the shard's " +
                                            std::to_string(end - begin) + " rows need " +
                                            std::to_string((end - begin) * K * Q));
        std::copy(values.begin(), values.end(), all.begin() + begin * K * Q);
    }
    return all;
}

std::string runMerge(const TaskContext& c, const CancelToken& cancel) {
    const auto start = std::chrono::steady_clock::now();
    const EnergyHistogram all = allEnergies(c);
    const int minBin = all.thresholdBin(c.plan.settings.energyFraction);
    TranslucentAsset asset = c.prepared.asset;
    asset.transfer = transferShell(c.plan, minBin, c.weights);
    // The rows tasks split E over harmonicSetFor(asset.samples) (toTransferSamples): the same set.
    asset.transfer.harmonicSet = harmonicSetFor(asset.samples);
    asset.transfer.harmonics = joinHarmonics(c, asset.transfer.harmonicSet.count);
    const std::vector<TaskFile> kept = stageFiles(c, FarmStage::Keep);
    for (std::size_t k = 0; k < c.plan.K(); ++k) {
        std::vector<KeptColumns> blocks;  // one k's kept coefficients, read once
        for (std::uint32_t s = 0; s < c.spec.shards; ++s) blocks.push_back(readKept(c, kept[s], s, k));
        KeptMatrixAssembler matrix(c.plan.n());
        for (const KeptColumns& block : blocks) matrix.count(block);
        for (KeptColumns& block : blocks) {
            matrix.fill(block);
            block = KeptColumns{};
        }
        asset.transfer.perBasis.push_back(matrix.take());
    }
    BakeReport report;
    report.warnings = c.prepared.warnings;
    report.transfer = transferStats(c.plan, asset.transfer, all.fractionFrom(minBin));
    finishBake(c.spec.options, asset, nullptr, cancel, &report);
    passCrashPoints(FarmStage::Merge, 0);
    writeBakedAsset(std::filesystem::path(c.spec.stem), asset, &report);
    if (const auto json = requestedReport(c.folder)) {
        addFarmStats(c, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), report);
        writeBakeReport(*json, c.spec.options, report);
    }
    // The asset is written: the intermediates are of no more use. The folder itself goes
    // last, so its absence (what --wait looks for) means nothing of the bake is left; a
    // folder renamed away first would still be there, under another name, when --wait
    // returned.
    std::error_code ignored;
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
