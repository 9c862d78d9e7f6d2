// `opal-bake batch MANIFEST.json [--json REPORT] [--quiet] [--farm local|slurm [--shards N]
// [--partition P] [--mem M] [--time T]]` (batch_manifest.h): bakes many assets, each in its
// own opal-bake process (its log in STEM.batch.log), so that one asset's crash or memory
// cannot take the others down. Plain and `--farm local`: one asset after another (a bake
// uses every CPU); `--farm slurm`: every asset's farm bake submitted at once, each
// followed by its own `opal-bake --wait` process. A farm bake writes the plain bake's bytes,
// so the key below does not record how an asset was baked.
//   - Skipped when unchanged: the asset's layer and the sidecar it names exist and
//     STEM.batch holds the key of this bake, XXH64 of opal-bake's own bytes, the input's
//     bytes (or the built-in name) and the arguments.
//   - A failed asset is retried once (a farm bake resumes from its tasks done); then it is
//     reported with the last line of its log.
//   - One summary: a table on stdout, failures first, and the same as JSON (--json).
// Exit codes: 0 every asset baked or skipped, 1 some asset failed (or the manifest is bad),
// 2 bad arguments, 130/143 interrupted (the asset being baked is left as it was).
#pragma once

#include "bake/progress.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace opal {

class BatchCommand {
public:
    // Adds the `batch` subcommand to `app` (which keeps pointers to this object's members).
    explicit BatchCommand(CLI::App& app);
    BatchCommand(const BatchCommand&) = delete;
    BatchCommand& operator=(const BatchCommand&) = delete;

    bool chosen() const { return command_->parsed(); }
    // Throws CLI::ValidationError for farm options without --farm (or Slurm's with local).
    void validate() const;
    int run(const CancelToken& cancel) const;

private:
    // What each asset's opal-bake gets for --farm (empty without).
    std::vector<std::string> farmArgs() const;

    CLI::App* command_;
    std::string manifest_, json_;
    bool quiet_ = false;
    std::string farm_, partition_, memory_, time_;
    std::optional<std::uint32_t> shards_;
};

}  // namespace opal
