// One task of a farm bake (farm_stage.h), run by `opal-bake farm-task FOLDER STAGE I`:
// reads its inputs from the farm folder (checking their checksums), runs its piece of the
// bake (bake_pipeline.h, transfer_stages.h) and writes its output atomically. A task
// whose output exists and checks out is not run again. Peak memory is bounded by the
// task's shard: a rows task holds its rows, a columns or keep task its block of columns,
// and only the merge holds the whole (compressed) transfer, as the asset does.
//
// Test hooks (schema/usd/crash_point.h): each task passes the crash points
// "farm:STAGE-I" (every attempt) and "farm:STAGE-I:attempt-A" (attempt A, from
// OPAL_FARM_ATTEMPT, which farm_task_runner.h sets) once its work is done, before its
// output is written.
#pragma once

#include "bake/farm/farm_stage.h"
#include "bake/progress.h"

#include <cstdint>
#include <string>

namespace opal {

inline constexpr const char* kFarmAttemptVariable = "OPAL_FARM_ATTEMPT";

struct FarmTaskResult {
    bool ranAlready = false;  // its verified output was there: nothing run
    std::string summary;      // for the log: what it did (the merge: the asset written)
};

// Throws opal::Error naming the task and the file at fault.
FarmTaskResult runFarmTask(const FarmFolder& folder, FarmStage stage, std::uint32_t index, const CancelToken& cancel);

}  // namespace opal
