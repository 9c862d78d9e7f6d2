// What a bake tells the pipeline: a JSON report (for machines) and a summary table in
// the form of the paper's Table 1 (for people): raw transfer, after step 1, after step 2.
#pragma once

#include "bake/bake_pipeline.h"

#include <filesystem>
#include <string>

namespace opal {

// Writes the report atomically. Keys: samples, charts, grid, subdivision_level, render_vertices, raw_bytes,
// step1_bytes, step2_bytes, sidecar_bytes, compression_ratio, energy_kept,
// transfer_rel_rmse, seconds {stage: s, total}, peak_rss_bytes, warnings, options; a farm
// bake adds farm {shards, stages: [{stage, tasks, measured, seconds_max, seconds_total,
// peak_rss_bytes}]} and its seconds are the merge task's, its peak_rss_bytes the largest task's.
void writeBakeReport(const std::filesystem::path& path, const BakeOptions& options, const BakeReport& report);

std::string formatBakeSummary(const std::filesystem::path& stem, const BakeReport& report);

// "sigmaS=MIN:MAX,sigmaA=MIN:MAX,eta=MIN:MAX" (mm^-1); throws opal::Error saying which
// part is malformed.
EditableRange parseEditableRange(const std::string& text);

// Peak resident memory of this process so far.
std::uint64_t peakRssBytes();

}  // namespace opal
