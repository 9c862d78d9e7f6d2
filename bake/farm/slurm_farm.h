// A farm bake on Slurm: one job array per stage (farm_stage.h), each task
// `opal-bake farm-run FOLDER STAGE` (farm_task_runner.h: one retry), chained with
// --dependency=afterok so a stage starts when the one before has finished. The first
// array is submitted held and released once every job id is recorded in FOLDER/jobs, so a
// task that fails twice can always cancel the stages after its own (cancelStagesAfter):
// nothing is left pending forever behind an afterok that can no longer be met.
#pragma once

#include "bake/farm/farm_stage.h"
#include "bake/progress.h"

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace opal {

struct SlurmOptions {
    std::string partition, memory, time;  // sbatch --partition --mem --time; empty: the cluster's default
};

using StageJobs = std::vector<std::pair<FarmStage, std::string>>;  // stage, job id

// Throws opal::Error when a job the folder records is still queued or running.
void refuseIfRunning(const FarmFolder& folder);

// Submits the folder's bake; returns the job ids (also in FOLDER/jobs).
StageJobs submitToSlurm(const FarmFolder& folder, const SlurmOptions& options);

StageJobs readStageJobs(const FarmFolder& folder);

// The bake's state: tasks done per stage, its jobs' Slurm states, the failure if any.
std::string farmStatus(const FarmFolder& folder, const std::filesystem::path& layer);

// scancel every recorded job (cancelFarm) or those of the stages after `stage`.
void cancelFarm(const FarmFolder& folder);
void cancelStagesAfter(const FarmFolder& folder, FarmStage stage);

// Follows the bake until the asset is written (0) or it fails (1, the failure printed):
// tasks done / total and an ETA on `progress`, from the outputs on disk and squeue.
int waitForFarm(const FarmFolder& folder, const std::filesystem::path& layer, std::FILE* progress,
                const CancelToken& cancel);

}  // namespace opal
