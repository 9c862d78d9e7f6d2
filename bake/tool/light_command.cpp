#include "bake/tool/light_command.h"

#include "bake/light/light_bake.h"
#include "bake/light/light_spec.h"

#include <cstdio>

namespace opal {

LightCommand::LightCommand(CLI::App& app)
    : command_(app.add_subcommand("light", "bake a local light's source radiance field (shadow field)")) {
    command_->add_option("spec", spec_, "the emitter: " + lightSpecHelp() + " (lengths in mm)")->required();
    command_->add_option("-o,--output", stem_, "output stem: writes STEM.usda and its sidecar STEM.<bake id>.opal")
        ->required();
    command_->add_option("--json", json_, "write a JSON report to this file");
    command_->add_flag("-q,--quiet", quiet_, "no progress output");
    command_->add_option("--shells", settings_.shells, "concentric spheres")
        ->check(CLI::Range(2u, 256u))
        ->capture_default_str();
    command_->add_option("--directions", settings_.directionFaceSize,
                         "sample directions per sphere: 6 x N x N (N a power of two)")
        ->check(CLI::IsMember({1u, 2u, 4u, 8u, 16u, 32u, 64u}))
        ->capture_default_str();
    command_->add_option("--map-size", settings_.mapFaceSize, "cube-map face size (power of two)")
        ->check(CLI::IsMember({1u, 2u, 4u, 8u, 16u, 32u, 64u, 128u, 256u}))
        ->capture_default_str();
    command_->add_option("--rays", settings_.raysPerTexelSide, "K x K stratified rays per edge texel")
        ->check(CLI::Range(1u, 64u))
        ->capture_default_str();
    command_->add_option("--inner", settings_.innerScale, "inner sphere radius / emitter radius (> 1)")
        ->check(CLI::Range(1.0 + 1e-9, 1e6))
        ->capture_default_str();
    command_->add_option("--outer", settings_.outerScale, "outer sphere radius / emitter radius")
        ->check(CLI::Range(1.0 + 1e-9, 1e6))
        ->capture_default_str();
    command_->add_option("--kept-energy", settings_.keptEnergy,
                         "per cube map, the fraction of its Haar energy kept (relative error <= sqrt(1 - it))")
        ->check(CLI::Range(1e-6, 1.0))
        ->capture_default_str();
    command_->add_option("--seed", settings_.seed, "random seed (same seed, same bytes)")->capture_default_str();
}

int LightCommand::run(ProgressSink* progress, const CancelToken& cancel) const {
    Emitter emitter;
    try {
        emitter = parseLightSpec(spec_);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "opal-bake light: %s\n", e.what());
        return 2;
    }
    try {
        const LightBakeReport report =
            bakeLightAsset(spec_, emitter, settings_, stem_, quiet_ ? nullptr : progress, cancel);
        for (const std::string& w : report.warnings) std::fprintf(stderr, "opal-bake: warning: %s\n", w.c_str());
        if (!json_.empty()) writeLightBakeReport(json_, report);
        if (!quiet_) std::fprintf(stderr, "%s", formatLightBakeSummary(report).c_str());
        return 0;
    } catch (const Cancelled&) {
        throw;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "opal-bake light: error: %s\n", e.what());
        return 1;
    }
}

}  // namespace opal
