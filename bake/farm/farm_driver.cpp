#include "bake/farm/farm_driver.h"

#include "bake/farm/child_process.h"
#include "bake/farm/farm_task_runner.h"
#include "schema/error.h"
#include "schema/usd/atomic_file.h"

#include <algorithm>

namespace opal {

FarmFolder setUpFarmFolder(const FarmSpec& spec, const std::filesystem::path& report) {
    const FarmFolder folder = FarmFolder::forStem(std::filesystem::absolute(spec.stem));
    std::error_code error;
    if (std::filesystem::exists(folder.spec(), error)) {
        bool same = false;
        try {
            same = encodeFarmSpec(readFarmSpec(folder)) == encodeFarmSpec(spec);
        } catch (const Error&) {
        }
        if (!same) std::filesystem::remove_all(folder.path());
    }
    std::filesystem::create_directories(folder.logs());
    std::filesystem::remove(folder.failed(), error);
    writeFarmSpec(folder, spec);
    if (report.empty())
        std::filesystem::remove(folder.reportRequest(), error);
    else
        writeFileAtomically(folder.reportRequest(), std::filesystem::absolute(report).string() + "\n");
    return folder;
}

LocalFarmResult runLocalFarm(const FarmFolder& folder, std::FILE* progress, const CancelToken& cancel) {
    const FarmSpec spec = readFarmSpec(folder);
    const std::filesystem::path self = selfExecutable();
    LocalFarmResult result;
    for (FarmStage stage : kFarmStages) {
        const std::uint32_t count = taskCount(stage, spec.shards);
        result.stagePeakRss.emplace_back(stage, 0);
        for (std::uint32_t i = 0; i < count; ++i) {
            if (progress)
                std::fprintf(progress, "opal-bake: farm local: %s %u/%u\n", std::string(stageName(stage)).c_str(),
                             i + 1, count);
            cancel.throwIfRequested();
            const TaskRun run = runTaskWithRetry(self, folder, stage, i, cancel);
            if (!run.ok) throw Error(run.error);
            ++result.tasks;
            if (run.attempts > 1) ++result.retried;
            result.stagePeakRss.back().second = std::max(result.stagePeakRss.back().second, run.peakRssBytes);
            if (run.peakRssBytes > result.largestTaskRss) {
                result.largestTaskRss = run.peakRssBytes;
                result.largestTask = taskName(stage, i);
            }
        }
    }
    return result;
}

}  // namespace opal
