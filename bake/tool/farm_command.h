// opal-bake's farm options and hidden subcommands (bake/farm/):
//   opal-bake MESH -o STEM --farm local [--shards N]
//   opal-bake MESH -o STEM --farm slurm [--shards N] [--partition P] [--mem M] [--time T] [--wait]
//   opal-bake --farm-status STEM | --farm-cancel STEM
//   opal-bake farm-task FOLDER STAGE I   one task (what the runner starts)
//   opal-bake farm-run FOLDER STAGE [I]  one task with a retry (what a Slurm job runs; I
//                                        from SLURM_ARRAY_TASK_ID when left out)
// Exit codes as opal-bake's: 0 done (or submitted), 1 error or a failed task, 2 bad arguments.
#pragma once

#include "bake/bake_pipeline.h"
#include "bake/progress.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace opal {

class FarmCommand {
public:
    // Adds the options and subcommands to `app` (which keeps pointers to this object).
    explicit FarmCommand(CLI::App& app);
    FarmCommand(const FarmCommand&) = delete;
    FarmCommand& operator=(const FarmCommand&) = delete;

    // A subcommand or --farm-status / --farm-cancel: no input or -o needed.
    bool standalone() const;
    // --farm given.
    bool farmBake() const { return !farm_.empty(); }
    // Checks the option combination; throws CLI::ValidationError.
    void validate() const;

    // Runs what was chosen (standalone() or farmBake()); returns the exit code. `report`:
    // --json's file (the merge task writes it), or empty.
    int run(const BakeOptions& options, const std::string& stem, const std::filesystem::path& report, bool quiet,
            const CancelToken& cancel) const;

private:
    int runTask(const CancelToken& cancel) const;
    int runWithRetry(const CancelToken& cancel) const;
    int bake(const BakeOptions& options, const std::string& stem, const std::filesystem::path& report, bool quiet,
             const CancelToken& cancel) const;

    CLI::App* task_;
    CLI::App* retry_;
    std::string farm_;
    std::uint32_t shards_ = 4;
    std::string partition_, memory_, time_;
    bool wait_ = false;
    std::string statusStem_, cancelStem_;
    std::string taskFolder_, taskStage_;
    std::optional<std::uint32_t> taskIndex_;
};

}  // namespace opal
