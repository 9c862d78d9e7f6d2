// The whole bake, stage by stage (docs/ARCHITECTURE.md#bake):
// import -> validate/repair -> subdivide -> sample -> parameterize -> fit basis ->
// transfer (two-step compression) -> environment visibility -> (write).
#pragma once

#include "bake/environment_visibility.h"
#include "bake/progress.h"
#include "bake/stem_lock.h"
#include "bake/transfer_builder.h"
#include "schema/asset/translucent_asset.h"

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace opal {

struct BakeOptions {
    std::string input;                // a mesh file, or a built-in mesh ("builtin:candle")
    // A Mesh prim of a .usda input ("/World/Statue"): bake that prim alone, in its own
    // space, named as the prim, and write the asset as an over-layer on it
    // (schema/asset/asset_over_layer.h). Empty: the whole input, merged.
    std::string applyTo;
    std::string scheme = "auto";      // auto | catmullClark | loop
    std::optional<std::uint32_t> level;  // uniform subdivision level; empty: automaticSubdivisionLevel
    std::uint64_t samples = 16384;    // N = M x 4^n
    double unitsPerMm = 1.0;          // scene units per millimetre
    std::optional<EditableRange> range;  // default: covering the ten presets
    std::string material = "marble";  // the asset's default material: a preset name
    // K. 16, not the paper's 12: a bake's basis reaches r_max = the asset's diagonal, and
    // there 12 functions miss the profiles' tails. Measured on the built-in candle in wax
    // (4,096 samples, lossless transfer, vs the exact dipole): K = 12 1.07% overall and
    // 4.2% on the candle's dim side, K = 16 0.07% and 0.14%. On the 65,536-sample bunny
    // K = 16 costs 153 s instead of 123 s and 6.0 GB instead of 4.5 GB at peak; the
    // sidecar hardly grows (step 2 spends little on the small-eigenvalue matrices).
    int basisCount = 16;
    TransferSettings transfer;
    VisibilitySettings visibility;
    std::uint64_t seed = 1;
};

// One stage of a farm bake, from its tasks' stats (bake/farm/task_stats.h).
struct StageTasks {
    std::string stage;       // "rows"
    std::uint32_t tasks = 0;
    std::uint32_t measured = 0;  // of `tasks`, those that left their stats
    double secondsMax = 0.0, secondsTotal = 0.0;
    std::uint64_t peakRssBytes = 0;  // the largest task's
};

struct BakeReport {
    std::uint64_t samples = 0;
    std::uint32_t charts = 0;
    std::uint32_t grid = 0;  // 2^n
    std::uint32_t subdivisionLevel = 0;  // the level used (chosen when BakeOptions::level is empty)
    std::uint64_t renderVertices = 0;
    TransferStats transfer;
    std::uint64_t sidecarBytes = 0;
    std::filesystem::path sidecarFile;  // STEM.<bake id>.opal, once written
    double transferRelRmse = 0.0;
    std::vector<std::pair<std::string, double>> seconds;  // per stage, in order
    std::uint64_t peakRssBytes = 0;  // a farm bake's: its largest task's
    std::vector<std::string> warnings;
    std::uint32_t farmShards = 0;       // 0: not a farm bake
    std::vector<StageTasks> farmStages;  // every stage, the merge last
};

// The stages before the transfer (import .. basis): the asset without its transfer and
// environment, its bake settings filled in. Throws opal::Error (or Cancelled).
TranslucentAsset prepareBake(const BakeOptions& options, ProgressSink* progress, const CancelToken& cancel,
                             BakeReport* report);

// The stages after the transfer, on the asset prepareBake gave and its transfer: the
// environment visibility, the transfer error, the bake identifier, the report's sizes.
void finishBake(const BakeOptions& options, TranslucentAsset& asset, ProgressSink* progress,
                const CancelToken& cancel, BakeReport* report);

// prepareBake, buildTransfer, finishBake: every stage up to a complete in-memory asset, with its bake identifier
// (bake_identifier.h). Throws opal::Error (or Cancelled).
TranslucentAsset bakeAsset(const BakeOptions& options, ProgressSink* progress, const CancelToken& cancel,
                           BakeReport* report);

// Replaces the asset at the locked stem as one unit (asset_stem.h): removes temporaries
// killed bakes left, writes the sidecar STEM.<bake id>.opal, then renames the layer
// STEM.usda into place (the commit), then removes the sidecars it superseded. Whenever the
// process dies, the stem holds the complete previous asset or the complete new one. Each
// step has a crash point (schema/usd/crash_point.h): bake:writing, bake:cleaned,
// opal:created/written/renamed, usda:created/written/renamed, bake:committed,
// bake:pruned-one, bake:pruned. Throws opal::Error naming the file; the previous asset is
// then intact. The asset must carry a bake identifier.
void writeBakedAsset(const StemLock& lock, const TranslucentAsset& asset, BakeReport* report,
                     const std::string& applyTo = {});

// The same, taking the stem's lock for the write.
void writeBakedAsset(const std::filesystem::path& stem, const TranslucentAsset& asset, BakeReport* report,
                     const std::string& applyTo = {});

// compressed vs exact transfer: RMS over >= 512 random output samples and RGB of the
// difference between sum_k s_k (T_k E) computed through the compressed transfer and
// exactly, for a point light's irradiance, relative to the exact RMS; both sides add the
// self term the relighter adds (SelfTerm::AtRunTime, which this requires).
double measureTransferError(const TranslucentAsset& asset, std::uint64_t seed);

}  // namespace opal
