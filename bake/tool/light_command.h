// `opal-bake light SPEC -o STEM [--json REPORT] [--quiet] [field settings]`: the subcommand
// that bakes a local light's source radiance field (bake/light/light_bake.h). SPEC syntax:
// bake/light/light_spec.h. Exit codes as the asset bake: 0 done, 1 error, 2 bad arguments
// (a bad spec or an unreadable emitter mesh included), 130/143 interrupted (nothing written).
#pragma once

#include "bake/light/field_bake.h"
#include "bake/progress.h"

#include <CLI/CLI.hpp>

#include <string>

namespace opal {

class LightCommand {
public:
    // Adds the `light` subcommand and its options to `app`, which keeps pointers to this
    // object's members: it must outlive the parse and stay where it is.
    explicit LightCommand(CLI::App& app);
    LightCommand(const LightCommand&) = delete;
    LightCommand& operator=(const LightCommand&) = delete;

    bool chosen() const { return command_->parsed(); }
    // Runs the bake; returns the process exit code.
    int run(ProgressSink* progress, const CancelToken& cancel) const;

private:
    CLI::App* command_;
    std::string spec_, stem_, json_;
    bool quiet_ = false;
    FieldSettings settings_;
};

}  // namespace opal
