// What a farm task cost: its wall time and its peak resident memory, as the task runner
// measured them around the `opal-bake farm-task` process (farm_task_runner.h), in
// FOLDER/stats/STAGE-I. The merge gathers them into the bake's report (--json), so a
// pipeline sees what every stage took on the farm, Slurm or local, without accounting.
#pragma once

#include "bake/bake_pipeline.h"
#include "bake/farm/farm_stage.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace opal {

struct TaskStats {
    double seconds = 0.0;            // every attempt, retries included
    std::uint64_t peakRssBytes = 0;  // the largest attempt's
    int attempts = 0;
};

// Written atomically; throws opal::Error naming the file.
void writeTaskStats(const FarmFolder& folder, FarmStage stage, std::uint32_t index, const TaskStats& stats);
// nullopt when the task left none (it ran under an older opal-bake, or its stats were lost);
// throws opal::Error naming the file when one is there but malformed.
std::optional<TaskStats> readTaskStats(const FarmFolder& folder, FarmStage stage, std::uint32_t index);

// Per stage before the merge: its tasks' largest and summed times and largest peak RSS,
// over the tasks that left stats (StageTasks::measured of StageTasks::tasks). A malformed
// stats file counts as unmeasured and adds a warning: the asset is written by then, and
// a report is no reason to fail it.
std::vector<StageTasks> gatherStageTasks(const FarmFolder& folder, std::uint32_t shards,
                                         std::vector<std::string>& warnings);

}  // namespace opal
