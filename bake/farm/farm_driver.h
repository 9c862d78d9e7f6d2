// What the opal-bake that starts a farm bake does: set up STEM.farm/ (or resume the one a
// previous run of the same bake left), then run its tasks here (--farm local) or submit
// them to Slurm (slurm_farm.h).
#pragma once

#include "bake/farm/farm_spec.h"
#include "bake/progress.h"

#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace opal {

// STEM.farm/ for `spec` (the folder's path absolute). A folder holding the same spec is
// resumed: its verified outputs stay and its `failed` note goes. A folder of another bake
// of the stem (other input or options) is emptied first. `report`: where the merge writes
// the bake's JSON report (made absolute), or empty for none.
FarmFolder setUpFarmFolder(const FarmSpec& spec, const std::filesystem::path& report);

struct LocalFarmResult {
    std::uint32_t tasks = 0, retried = 0;
    std::uint64_t largestTaskRss = 0;
    std::string largestTask;  // "rows 2"
    std::vector<std::pair<FarmStage, std::uint64_t>> stagePeakRss;  // the largest task's, per stage
};

// Runs every task of the folder's bake on this machine, stage after stage, each as its
// own process (farm_task_runner.h), reporting progress on `progress` (may be null).
// Throws opal::Error with the failed task's note when a task fails twice.
// Throws Cancelled when `cancel` is requested.
LocalFarmResult runLocalFarm(const FarmFolder& folder, std::FILE* progress, const CancelToken& cancel);

}  // namespace opal
