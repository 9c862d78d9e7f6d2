#include "bake/farm/task_stats.h"

#include "schema/error.h"
#include "schema/usd/atomic_file.h"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace opal {

void writeTaskStats(const FarmFolder& folder, FarmStage stage, std::uint32_t index, const TaskStats& stats) {
    std::filesystem::create_directories(folder.stats(stage, index).parent_path());
    char text[160];
    std::snprintf(text, sizeof text, "seconds %.6f\npeak_rss_bytes %" PRIu64 "\nattempts %d\n", stats.seconds,
                  stats.peakRssBytes, stats.attempts);
    writeFileAtomically(folder.stats(stage, index), text);
}

std::optional<TaskStats> readTaskStats(const FarmFolder& folder, FarmStage stage, std::uint32_t index) {
    const std::filesystem::path file = folder.stats(stage, index);
    std::ifstream in(file);
    if (!in) return std::nullopt;
    TaskStats stats;
    std::string key1, key2, key3;
    in >> key1 >> stats.seconds >> key2 >> stats.peakRssBytes >> key3 >> stats.attempts;
    if (!in || key1 != "seconds" || key2 != "peak_rss_bytes" || key3 != "attempts" || !std::isfinite(stats.seconds) ||
        stats.seconds < 0.0 || stats.attempts < 1)
        throw Error(file.string() + ": not a task's stats (expected 'seconds S', 'peak_rss_bytes B', 'attempts A')");
    return stats;
}

std::vector<StageTasks> gatherStageTasks(const FarmFolder& folder, std::uint32_t shards,
                                         std::vector<std::string>& warnings) {
    std::vector<StageTasks> stages;
    for (FarmStage stage : kFarmStages) {
        if (stage == FarmStage::Merge) continue;
        StageTasks s;
        s.stage = std::string(stageName(stage));
        s.tasks = taskCount(stage, shards);
        for (std::uint32_t i = 0; i < s.tasks; ++i) {
            std::optional<TaskStats> t;
            try {
                t = readTaskStats(folder, stage, i);
            } catch (const Error& e) {
                warnings.push_back(e.what());
            }
            if (!t) continue;
            ++s.measured;
            s.secondsMax = std::max(s.secondsMax, t->seconds);
            s.secondsTotal += t->seconds;
            s.peakRssBytes = std::max(s.peakRssBytes, t->peakRssBytes);
        }
        stages.push_back(s);
    }
    return stages;
}

}  // namespace opal
