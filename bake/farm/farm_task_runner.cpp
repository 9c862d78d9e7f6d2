#include "bake/farm/farm_task_runner.h"

#include "bake/farm/child_process.h"
#include "bake/farm/farm_task.h"
#include "bake/farm/task_stats.h"
#include "schema/usd/atomic_file.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>

namespace opal {

namespace {

constexpr int kAttempts = 2;

std::string lastLine(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::string line, last;
    while (std::getline(in, line))
        if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
    return last;
}

void note(const std::filesystem::path& log, const std::string& text) {
    std::ofstream out(log, std::ios::app);
    out << "opal-bake farm: " << text << '\n';
}

}  // namespace

TaskRun runTaskWithRetry(const std::filesystem::path& opalBake, const FarmFolder& folder, FarmStage stage,
                         std::uint32_t index, const CancelToken& cancel) {
    std::filesystem::create_directories(folder.logs());
    const std::filesystem::path log = folder.log(stage, index);
    TaskRun run;
    std::vector<std::string> endings;
    std::string lastOutput;
    const auto start = std::chrono::steady_clock::now();
    for (int attempt = 1; attempt <= kAttempts; ++attempt) {
        note(log, "task " + taskName(stage, index) + ", attempt " + std::to_string(attempt));
        const ChildExit e = runLogged(opalBake,
                                      {"farm-task", folder.path().string(), std::string(stageName(stage)),
                                       std::to_string(index)},
                                      log, {std::string(kFarmAttemptVariable) + "=" + std::to_string(attempt)});
        run.attempts = attempt;
        run.peakRssBytes = std::max(run.peakRssBytes, e.peakRssBytes);
        if (e.ok()) {
            run.ok = true;
            // The merge removed the folder: its cost is in the report it wrote itself.
            if (stage != FarmStage::Merge)
                writeTaskStats(folder, stage, index,
                               {std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                                run.peakRssBytes, attempt});
            return run;
        }
        if (cancel.requested()) note(log, "interrupted (" + e.describe() + ")");
        cancel.throwIfRequested();
        endings.push_back(e.describe());
        lastOutput = lastLine(log);
        note(log, "attempt " + std::to_string(attempt) + " failed (" + e.describe() + ")");
    }
    std::ostringstream s;
    s << "farm task " << taskName(stage, index) << " failed twice (";
    for (std::size_t i = 0; i < endings.size(); ++i) s << (i ? ", then " : "") << endings[i];
    s << "); its log: " << log.string();
    if (!lastOutput.empty()) s << " (last line: " << lastOutput << ")";
    run.error = s.str();
    writeFileAtomically(folder.failed(), run.error + "\n");
    return run;
}

}  // namespace opal
