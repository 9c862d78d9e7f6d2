#include "bake/tool/farm_command.h"

#include "bake/asset_stem.h"
#include "bake/farm/child_process.h"
#include "bake/farm/farm_driver.h"
#include "bake/farm/farm_task.h"
#include "bake/farm/farm_task_runner.h"
#include "bake/farm/slurm_farm.h"
#include "bake/procedural_mesh.h"
#include "bake/sample_count.h"
#include "schema/error.h"

#include <tbb/global_control.h>

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <memory>

namespace opal {

namespace {

FarmStage stageArgument(const std::string& name) {
    const std::optional<FarmStage> stage = parseStage(name);
    if (!stage) throw Error("farm: unknown stage '" + name + "' (prepare, rows, columns, keep or merge)");
    return *stage;
}

// A task uses the CPUs Slurm gave it, when it says.
std::unique_ptr<tbb::global_control> slurmCpuLimit() {
    const char* cpus = std::getenv("SLURM_CPUS_PER_TASK");
    if (!cpus) return nullptr;
    const long n = std::strtol(cpus, nullptr, 10);
    if (n <= 0) return nullptr;
    return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, std::size_t(n));
}

std::uint32_t arrayIndex() {
    const char* id = std::getenv("SLURM_ARRAY_TASK_ID");
    if (!id) throw Error("farm-run: no task index given and SLURM_ARRAY_TASK_ID is not set");
    return std::uint32_t(std::strtoul(id, nullptr, 10));
}

}  // namespace

FarmCommand::FarmCommand(CLI::App& app) {
    app.add_option("--farm", farm_, "bake as farm tasks: local (on this machine) or slurm (submitted with sbatch)")
        ->check(CLI::IsMember({"local", "slurm"}));
    app.add_option("--shards", shards_, "farm: rows and column blocks the transfer is cut into")
        ->check(CLI::Range(1u, 4096u))
        ->capture_default_str();
    app.add_option("--partition", partition_, "farm slurm: sbatch --partition");
    app.add_option("--mem", memory_, "farm slurm: sbatch --mem per task (e.g. 8G)");
    app.add_option("--time", time_, "farm slurm: sbatch --time per task (e.g. 1:00:00)");
    app.add_flag("--wait", wait_, "farm slurm: follow the bake until the asset is written or it fails");
    app.add_option("--farm-status", statusStem_, "report on the farm bake of STEM")->type_name("STEM");
    app.add_option("--farm-cancel", cancelStem_, "cancel the farm bake of STEM (scancel its jobs)")->type_name("STEM");
    task_ = app.add_subcommand("farm-task", "")->group("");  // hidden: what the farm runs
    task_->add_option("folder", taskFolder_)->required();
    task_->add_option("stage", taskStage_)->required();
    task_->add_option("index", taskIndex_)->required();
    retry_ = app.add_subcommand("farm-run", "")->group("");
    retry_->add_option("folder", taskFolder_)->required();
    retry_->add_option("stage", taskStage_)->required();
    retry_->add_option("index", taskIndex_);
}

bool FarmCommand::standalone() const {
    return task_->parsed() || retry_->parsed() || !statusStem_.empty() || !cancelStem_.empty();
}

void FarmCommand::validate() const {
    if (farm_.empty()) return;
    if (farm_ == "local" && (wait_ || !partition_.empty() || !memory_.empty() || !time_.empty()))
        throw CLI::ValidationError("--farm local", "--wait, --partition, --mem and --time are for --farm slurm");
}

int FarmCommand::run(const BakeOptions& options, const std::string& stem, const std::filesystem::path& report,
                     bool quiet, const CancelToken& cancel) const {
    if (task_->parsed()) return runTask(cancel);
    if (retry_->parsed()) return runWithRetry(cancel);
    if (!statusStem_.empty()) {
        const AssetStem asset(statusStem_);
        std::fputs(farmStatus(FarmFolder::forStem(std::filesystem::absolute(statusStem_)), asset.layer()).c_str(),
                   stdout);
        return 0;
    }
    if (!cancelStem_.empty()) {
        const FarmFolder folder = FarmFolder::forStem(std::filesystem::absolute(cancelStem_));
        cancelFarm(folder);
        std::printf("opal-bake: cancelled the jobs of %s\n", folder.path().c_str());
        return 0;
    }
    return bake(options, stem, report, quiet, cancel);
}

int FarmCommand::runTask(const CancelToken& cancel) const {
    const FarmFolder folder(std::filesystem::absolute(taskFolder_));
    const FarmSpec spec = readFarmSpec(folder);
    // The bake's relative paths (input, stem) are the submitting opal-bake's.
    if (chdir(spec.workingDirectory.c_str()) != 0)
        throw Error(spec.workingDirectory + ": cannot enter the bake's working folder: " + std::strerror(errno));
    const auto cpuLimit = slurmCpuLimit();
    const FarmTaskResult result = runFarmTask(folder, stageArgument(taskStage_), *taskIndex_, cancel);
    std::printf("opal-bake farm-task %s %s: %s\n", taskStage_.c_str(), std::to_string(*taskIndex_).c_str(),
                result.ranAlready ? "its output was there already" : "done");
    std::fputs(result.summary.c_str(), stdout);
    return 0;
}

int FarmCommand::runWithRetry(const CancelToken& cancel) const {
    const FarmFolder folder(std::filesystem::absolute(taskFolder_));
    const FarmStage stage = stageArgument(taskStage_);
    const TaskRun run =
        runTaskWithRetry(selfExecutable(), folder, stage, taskIndex_ ? *taskIndex_ : arrayIndex(), cancel);
    if (run.ok) return 0;
    std::fprintf(stderr, "opal-bake: error: %s\n", run.error.c_str());
    if (std::filesystem::exists(folder.jobs())) cancelStagesAfter(folder, stage);
    return 1;
}

int FarmCommand::bake(const BakeOptions& options, const std::string& stem, const std::filesystem::path& report,
                      bool quiet, const CancelToken& cancel) const {
    // What the prepare task would refuse, refused before anything is set up or submitted.
    (void)chartLayoutForSampleCount(options.samples);
    std::error_code error;
    if (!builtinMesh(options.input) && !std::filesystem::is_regular_file(options.input, error))
        throw Error(options.input + ": no such input file");
    // The merge writes the report once the asset is written: a folder that is not there
    // would fail the bake at its very end.
    if (!report.empty() && !std::filesystem::is_directory(std::filesystem::absolute(report).parent_path(), error))
        throw Error(report.string() + ": --json: its folder does not exist");
    FarmSpec spec;
    spec.options = options;
    spec.stem = stem;
    spec.workingDirectory = std::filesystem::current_path().string();
    spec.shards = shards_;
    const AssetStem asset(stem);
    std::FILE* progress = quiet ? nullptr : stderr;
    if (farm_ == "local") {
        const FarmFolder folder = setUpFarmFolder(spec, report);
        const LocalFarmResult result = runLocalFarm(folder, progress, cancel);
        if (!quiet)
            std::fprintf(stderr,
                         "opal-bake: farm local: %u tasks (%u retried), largest task peak RSS %.1f MiB (%s); "
                         "wrote %s\n",
                         result.tasks, result.retried, double(result.largestTaskRss) / (1024.0 * 1024.0),
                         result.largestTask.c_str(), asset.layer().c_str());
        if (!quiet) {
            std::string stages;
            for (const auto& [stage, rss] : result.stagePeakRss)
                stages += (stages.empty() ? "" : ", ") + std::string(stageName(stage)) + " " +
                          std::to_string((rss + (1 << 19)) >> 20);
            std::fprintf(stderr, "opal-bake: farm local: peak RSS of the largest task per stage (MiB): %s\n",
                         stages.c_str());
        }
        return 0;
    }
    refuseIfRunning(FarmFolder::forStem(std::filesystem::absolute(stem)));
    const FarmFolder folder = setUpFarmFolder(spec, report);
    const StageJobs jobs = submitToSlurm(folder, SlurmOptions{partition_, memory_, time_});
    for (const auto& [stage, id] : jobs) std::printf("%s %s\n", std::string(stageName(stage)).c_str(), id.c_str());
    std::fflush(stdout);
    if (!wait_) return 0;
    const int code = waitForFarm(folder, asset.layer(), progress, cancel);
    if (code == 0 && !quiet) std::fprintf(stderr, "opal-bake: farm slurm: wrote %s\n", asset.layer().c_str());
    return code;
}

}  // namespace opal
