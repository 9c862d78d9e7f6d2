// Runs one farm task with one retry, the same way on this machine (--farm local) and in a
// Slurm job (`opal-bake farm-run`): `opal-bake farm-task FOLDER STAGE I` as a child
// process, its output appended to the task's log (FOLDER/logs/STAGE-I.log), and when it
// fails (an error, a crash, a kill) once more. When the second attempt fails too, it
// writes FOLDER/failed: the task, how both attempts ended, its log and the log's last
// line; that is what --wait and --farm-status report. A task that succeeds leaves its
// time and peak memory in FOLDER/stats/ (task_stats.h) for the bake's report.
#pragma once

#include "bake/farm/farm_stage.h"
#include "bake/progress.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace opal {

struct TaskRun {
    bool ok = false;
    int attempts = 0;
    std::uint64_t peakRssBytes = 0;  // the largest of the attempts
    std::string error;               // when !ok: what FOLDER/failed says
};

// Throws Cancelled (no retry, no failure recorded) when `cancel` is requested by the time
// an attempt fails: an interrupted bake, or Slurm cancelling the job, is not a task's fault.
TaskRun runTaskWithRetry(const std::filesystem::path& opalBake, const FarmFolder& folder, FarmStage stage,
                         std::uint32_t index, const CancelToken& cancel);

}  // namespace opal
