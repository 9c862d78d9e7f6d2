#include "bake/farm/slurm_farm.h"

#include "bake/farm/child_process.h"
#include "bake/farm/farm_spec.h"
#include "schema/error.h"
#include "schema/usd/atomic_file.h"

#include <chrono>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

namespace opal {

namespace {

std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
    return s;
}

// Runs a Slurm command; throws naming it and what it printed when it fails.
std::string slurm(const std::vector<std::string>& args) {
    const ChildExit e = runCommand(args);
    if (!e.ok()) {
        std::string command;
        for (const std::string& a : args) command += (command.empty() ? "" : " ") + a;
        throw Error(command + ": " + e.describe() + ": " + trimmed(e.err.empty() ? e.out : e.err));
    }
    return e.out;
}

// Job id -> state of the folder's jobs still in the queue (array tasks: the worst state).
std::map<std::string, std::string> queuedStates(const StageJobs& jobs) {
    std::map<std::string, std::string> states;
    if (jobs.empty()) return states;
    std::istringstream lines(slurm({"squeue", "-h", "-o", "%F %T"}));
    std::string id, state;
    while (lines >> id >> state)
        for (const auto& job : jobs)
            if (job.second == id && (states[id].empty() || state == "RUNNING")) states[id] = state;
    return states;
}

struct Progress {
    std::uint32_t done = 0, total = 0;
    std::string current;  // "rows 3/4": the first stage not complete
};

Progress progressOf(const FarmFolder& folder, std::uint32_t shards) {
    Progress p;
    std::error_code error;
    for (FarmStage stage : kFarmStages) {
        const std::uint32_t count = taskCount(stage, shards);
        std::uint32_t done = 0;
        if (stage != FarmStage::Merge)
            for (std::uint32_t i = 0; i < count; ++i) done += std::filesystem::exists(folder.output(stage, i), error);
        p.done += done;
        p.total += count;
        if (p.current.empty() && done < count)
            p.current = std::string(stageName(stage)) + " " + std::to_string(done) + "/" + std::to_string(count);
    }
    return p;
}

std::string sbatchWrap(const FarmFolder& folder, FarmStage stage) {
    return "exec " + shellQuoted(selfExecutable().string()) + " farm-run " + shellQuoted(folder.path().string()) + " " +
           std::string(stageName(stage));
}

}  // namespace

StageJobs readStageJobs(const FarmFolder& folder) {
    StageJobs jobs;
    std::istringstream lines(readText(folder.jobs()));
    std::string stage, id;
    while (lines >> stage >> id)
        if (const auto s = parseStage(stage)) jobs.emplace_back(*s, id);
    return jobs;
}

void refuseIfRunning(const FarmFolder& folder) {
    const StageJobs jobs = readStageJobs(folder);
    const auto states = queuedStates(jobs);
    if (states.empty()) return;
    std::string ids;
    for (const auto& [id, state] : states) ids += (ids.empty() ? "" : ", ") + id + " " + state;
    throw Error(folder.path().string() + ": this bake is still on the farm (jobs " + ids +
                "); see opal-bake --farm-status, or stop it with --farm-cancel");
}

StageJobs submitToSlurm(const FarmFolder& folder, const SlurmOptions& options) {
    const std::uint32_t shards = readFarmSpec(folder).shards;
    StageJobs jobs;
    for (FarmStage stage : kFarmStages) {
        const std::string name(stageName(stage));
        std::vector<std::string> args = {"sbatch", "--parsable", "--job-name=opal-" + name,
                                         "--array=0-" + std::to_string(taskCount(stage, shards) - 1),
                                         "--output=" + (folder.logs() / (name + "-%a.log")).string(),
                                         "--open-mode=append"};
        if (!options.partition.empty()) args.push_back("--partition=" + options.partition);
        if (!options.memory.empty()) args.push_back("--mem=" + options.memory);
        if (!options.time.empty()) args.push_back("--time=" + options.time);
        if (jobs.empty()) args.push_back("--hold");
        else args.push_back("--dependency=afterok:" + jobs.back().second);
        args.push_back("--wrap=" + sbatchWrap(folder, stage));
        std::string id;
        try {
            id = trimmed(slurm(args));
        } catch (const Error&) {
            for (const auto& job : jobs) runCommand({"scancel", job.second});
            throw;
        }
        id = id.substr(0, id.find(';'));  // "id;cluster" on multi-cluster setups
        jobs.emplace_back(stage, id);
    }
    std::string text;
    for (const auto& [stage, id] : jobs) text += std::string(stageName(stage)) + " " + id + "\n";
    writeFileAtomically(folder.jobs(), text);
    slurm({"scontrol", "release", jobs.front().second});
    return jobs;
}

std::string farmStatus(const FarmFolder& folder, const std::filesystem::path& layer) {
    std::ostringstream s;
    std::error_code error;
    if (!std::filesystem::exists(folder.path(), error)) {
        s << folder.path().string() << ": no farm bake here"
          << (std::filesystem::exists(layer, error) ? " (the asset " + layer.string() + " is written)" : "") << '\n';
        return s.str();
    }
    const std::uint32_t shards = readFarmSpec(folder).shards;
    const Progress p = progressOf(folder, shards);
    s << folder.path().string() << ": " << p.done << "/" << p.total << " tasks done";
    if (!p.current.empty()) s << " (now: " << p.current << ")";
    s << '\n';
    const StageJobs jobs = readStageJobs(folder);
    const auto states = queuedStates(jobs);
    for (const auto& [stage, id] : jobs) {
        const auto state = states.find(id);
        s << "  " << stageName(stage) << ": job " << id << " "
          << (state == states.end() ? "not queued" : state->second) << '\n';
    }
    if (std::filesystem::exists(folder.failed(), error)) s << "failed: " << trimmed(readText(folder.failed())) << '\n';
    return s.str();
}

void cancelFarm(const FarmFolder& folder) {
    std::vector<std::string> args = {"scancel"};
    for (const auto& job : readStageJobs(folder)) args.push_back(job.second);
    if (args.size() > 1) slurm(args);
}

void cancelStagesAfter(const FarmFolder& folder, FarmStage stage) {
    std::vector<std::string> args = {"scancel"};
    for (const auto& job : readStageJobs(folder))
        if (int(job.first) > int(stage)) args.push_back(job.second);
    if (args.size() > 1) slurm(args);
}

int waitForFarm(const FarmFolder& folder, const std::filesystem::path& layer, std::FILE* progress,
                const CancelToken& cancel) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const std::uint32_t shards = readFarmSpec(folder).shards;
    const StageJobs jobs = readStageJobs(folder);
    const std::uint32_t doneAtStart = progressOf(folder, shards).done;
    std::string shown;
    int goneChecks = 0;
    std::error_code error;
    for (;;) {
        cancel.throwIfRequested();
        if (std::filesystem::exists(folder.failed(), error)) {
            std::fprintf(stderr, "opal-bake: error: %s\n", trimmed(readText(folder.failed())).c_str());
            return 1;
        }
        if (!std::filesystem::exists(folder.path(), error)) {  // the merge removes it once the asset is written
            if (std::filesystem::exists(layer, error)) return 0;
            std::fprintf(stderr, "opal-bake: error: %s is gone but %s was not written\n", folder.path().c_str(),
                         layer.c_str());
            return 1;
        }
        const Progress p = progressOf(folder, shards);
        if (!std::filesystem::exists(folder.path(), error)) continue;  // removed while counting: the merge is done
        const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        std::ostringstream line;
        line << "opal-bake: farm: " << p.done << "/" << p.total << " tasks done";
        if (!p.current.empty()) line << " (" << p.current << ")";
        if (progress && line.str() != shown) {  // a line when a task is done, with the ETA then
            shown = line.str();
            if (p.done > doneAtStart)
                line << ", ETA " << int(elapsed * double(p.total - p.done) / double(p.done - doneAtStart) + 0.5)
                     << " s";
            std::fprintf(progress, "%s\n", line.str().c_str());
        }
        // Jobs all gone from the queue, yet neither the asset nor a failure: cancelled, or
        // killed by Slurm (time limit, memory) before the runner could record it.
        goneChecks = queuedStates(jobs).empty() ? goneChecks + 1 : 0;
        if (goneChecks >= 3 && std::filesystem::exists(folder.path(), error) &&
            !std::filesystem::exists(folder.failed(), error)) {
            std::fprintf(stderr, "opal-bake: error: the bake's Slurm jobs left the queue without writing %s "
                                 "(cancelled, or stopped by Slurm); logs in %s\n",
                         layer.c_str(), folder.logs().c_str());
            return 1;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
    }
}

}  // namespace opal
