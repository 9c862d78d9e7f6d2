// A farm bake's stages, in order, and the folder its tasks share (STEM.farm/):
//   prepare  1 task   import .. basis (bake_pipeline.h prepareBake)  -> prepared.task
//   rows     N tasks  step 1 for a range of output rows              -> rows-I.task
//                     (one section per k and column block)
//   columns  N tasks  a block of columns gathered from every rows     -> columns-I.task
//                     shard, step 2's energy histogram over them      (the histogram)
//   keep     N tasks  the threshold from all histograms; the block    -> kept-I.task
//                     gathered again, its kept 9/7 coefficients
//   merge    1 task   the matrices assembled block by block, environment visibility,
//                     the transfer error, the asset written (asset_stem.h); the folder removed
// The folder also holds spec.task (what to bake, written by the submitting opal-bake),
// jobs (Slurm job ids per stage), failed (why the bake stopped), logs/STAGE-I.log,
// stats/STAGE-I (what each task cost) and report-path (where --json wants the report).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace opal {

enum class FarmStage { Prepare, Rows, Columns, Keep, Merge };
inline constexpr FarmStage kFarmStages[] = {FarmStage::Prepare, FarmStage::Rows, FarmStage::Columns, FarmStage::Keep,
                                            FarmStage::Merge};

std::string_view stageName(FarmStage stage);
std::optional<FarmStage> parseStage(std::string_view name);
std::uint32_t taskCount(FarmStage stage, std::uint32_t shards);

// Shard i of [0, n) cut into `shards` contiguous ranges of near-equal size.
std::pair<std::size_t, std::size_t> shardRange(std::size_t n, std::uint32_t shards, std::uint32_t i);

class FarmFolder {
public:
    explicit FarmFolder(std::filesystem::path path) : path_(std::move(path)) {}
    // STEM.farm next to the stem's layer.
    static FarmFolder forStem(const std::filesystem::path& stem);

    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path spec() const { return path_ / "spec.task"; }
    std::filesystem::path jobs() const { return path_ / "jobs"; }
    std::filesystem::path failed() const { return path_ / "failed"; }
    // What task (stage, i) writes; the merge's is the asset, so it has none here.
    std::filesystem::path output(FarmStage stage, std::uint32_t i) const;
    std::filesystem::path log(FarmStage stage, std::uint32_t i) const;
    std::filesystem::path logs() const { return path_ / "logs"; }
    // What task (stage, i) cost (task_stats.h).
    std::filesystem::path stats(FarmStage stage, std::uint32_t i) const;
    // The JSON report the submitting opal-bake asked for (--json): the merge writes it.
    std::filesystem::path reportRequest() const { return path_ / "report-path"; }

private:
    std::filesystem::path path_;
};

// "rows 3": how errors and logs name a task.
std::string taskName(FarmStage stage, std::uint32_t i);

}  // namespace opal
