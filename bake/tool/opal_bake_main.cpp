// opal-bake INPUT -o OUT_STEM [options]: bakes a mesh into an Opal asset (OUT_STEM.usda +
// OUT_STEM.<bake id>.opal, bake/asset_stem.h). opal-bake light SPEC -o OUT_STEM [options]:
// bakes a local light's shadow field (bake/tool/light_command.h). opal-bake batch
// MANIFEST.json: bakes many assets (bake/tool/batch_command.h). opal-bake INPUT -o OUT_STEM
// --farm local|slurm: the same bake as farm tasks (bake/tool/farm_command.h). opal-bake
// INPUT.usda --apply-to /Path/To/Mesh -o OUT_STEM: that one prim, written as an over-layer on
// it (schema/asset/asset_over_layer.h). Exit codes: 0
// done, 1 error (including another bake writing the same stem), 2 bad arguments, 130/143
// interrupted by SIGINT/SIGTERM (nothing written; a previous asset stays intact). The bytes
// do not depend on the processor (bake/tool/baseline_math.h, raytrace/embree_device_config.h).
#include "bake/bake_pipeline.h"
#include "bake/bake_report.h"
#include "bake/procedural_mesh.h"
#include "bake/tool/allocator_tuning.h"
#include "bake/tool/baseline_math.h"
#include "bake/tool/batch_command.h"
#include "bake/tool/farm_command.h"
#include "bake/tool/light_command.h"
#include "schema/error.h"

#include <CLI/CLI.hpp>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <iostream>

namespace {

// The only global: a signal handler can reach nothing else. Lock-free, so setting it is
// async-signal-safe.
std::atomic<bool> gInterrupted{false};
volatile std::sig_atomic_t gSignal = 0;

extern "C" void onSignal(int signal) {
    gSignal = signal;
    gInterrupted.store(true);
}

void installSignalHandlers() {
    struct sigaction action {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

opal::EditableRange parseRange(const std::string& text) {
    return opal::parseEditableRange(text);
}

}  // namespace

int main(int argc, char** argv) {
    try {
        opal::runOnBaselineMath(argv);  // may restart the process: before anything else
    } catch (const opal::Error& e) {
        std::fprintf(stderr, "opal-bake: error: %s\n", e.what());
        return 1;
    }
    opal::keepAllocatorMemory();
    CLI::App app{"opal-bake: bake a mesh into a relightable translucent Opal asset"};
    opal::BakeOptions options;
    std::string outStem, jsonPath, range;
    bool quiet = false;
    // Required unless a subcommand (`light`, `batch`) is given (checked after parsing).
    app.add_option("input", options.input,
                   "mesh file (.obj .ply .gltf .glb .stl .usda) or a built-in mesh: " + opal::builtinMeshNames());
    app.add_option("-o,--output", outStem, "output stem: writes STEM.usda and its sidecar STEM.<bake id>.opal");
    app.add_option("--apply-to", options.applyTo,
                   "a Mesh prim of the .usda input (/World/Statue): bake it alone, in its own space, and write "
                   "STEM.usda as an over-layer on that prim to sublayer over the input");
    opal::LightCommand light(app);  // not const: parsing writes its options
    opal::BatchCommand batch(app);
    opal::FarmCommand farm(app);
    app.require_subcommand(0, 1);
    app.add_option("--scheme", options.scheme,
                   "subdivision scheme; auto: a .usda's subdivisionScheme, else loop for all-triangle meshes, "
                   "else catmullClark")
        ->check(CLI::IsMember({"auto", "catmullClark", "loop"}))
        ->capture_default_str();
    std::string level = "auto";
    app.add_option("--level", level,
                   "uniform subdivision level 0-6, or auto: the coarsest level with at least as many render-mesh "
                   "vertices as samples")
        ->check(CLI::IsMember({"auto", "0", "1", "2", "3", "4", "5", "6"}))
        ->capture_default_str();
    app.add_option("--samples", options.samples, "surface samples N = M x 4^n (e.g. 16384 = 4 x 64 x 64)")
        ->capture_default_str();
    app.add_option("--units-per-mm", options.unitsPerMm, "scene units per millimetre")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    app.add_option("--range", range,
                   "editable range: 'presets' (default) or sigmaS=MIN:MAX,sigmaA=MIN:MAX,eta=MIN:MAX (mm^-1; eta within [1, 3])");
    app.add_option("--material", options.material, "default material preset")->capture_default_str();
    app.add_option("--basis", options.basisCount, "PCA basis functions K")->check(CLI::Range(1, 64))->capture_default_str();
    app.add_option("--keep", options.transfer.keepFraction, "step 1: fraction of Haar coefficients kept per row")
        ->check(CLI::Range(1e-6, 1.0))
        ->capture_default_str();
    app.add_option("--keep-min", options.transfer.minPerRow,
                   "step 1: but at least this many Haar coefficients per row (on average over the basis)")
        ->check(CLI::Range(1u, 1u << 30))
        ->capture_default_str();
    app.add_option("--energy", options.transfer.energyFraction,
                   "step 2: fraction of the weighted CDF 9/7 energy kept; the transfer's relative error is about "
                   "sqrt(1 - energy)")
        ->check(CLI::Range(1e-6, 1.0))
        ->capture_default_str();
    app.add_option("--env-res", options.visibility.cubeFaceSize, "environment cube map face size (power of two)")
        ->capture_default_str();
    app.add_option("--env-terms", options.visibility.terms, "the most Haar terms one sample keeps for the environment")
        ->capture_default_str();
    app.add_option("--env-error", options.visibility.error,
                   "environment: per sample, the dropped terms hold at most about this fraction of an open "
                   "sample's E")
        ->check(CLI::Range(0.0, 1.0))
        ->capture_default_str();
    app.add_option("--seed", options.seed, "random seed (same seed, same bytes)")->capture_default_str();
    app.add_option("--json", jsonPath, "write a JSON report to this file");
    app.add_flag("-q,--quiet", quiet, "no progress output");
    try {
        app.parse(argc, argv);
        const bool subcommand = light.chosen() || batch.chosen() || farm.standalone();
        if (!subcommand && options.input.empty()) throw CLI::RequiredError("input");
        if (!subcommand && outStem.empty()) throw CLI::RequiredError("--output");
        farm.validate();
        batch.validate();
        if (!options.applyTo.empty() && (farm.farmBake() || farm.standalone() || light.chosen() || batch.chosen()))
            throw CLI::ValidationError("--apply-to", "bakes on this machine only (not with --farm, light or batch)");
        if (!range.empty() && range != "presets") options.range = parseRange(range);
        if (level != "auto") options.level = std::uint32_t(std::stoul(level));
    } catch (const CLI::ParseError& e) {
        // app.exit prints the message; CLI11's own codes (105 for a failed check, 106 for a
        // missing option, ...) would break the documented contract: bad arguments exit 2.
        return app.exit(e) == 0 ? 0 : 2;  // --help exits 0
    } catch (const opal::Error& e) {
        std::fprintf(stderr, "opal-bake: --range: %s\n", e.what());
        return 2;
    }

    installSignalHandlers();
    opal::ProgressBar progress(stderr, opal::ProgressBar::styleFor(stderr, quiet));
    const opal::CancelToken cancel(&gInterrupted);
    try {
        if (light.chosen()) return light.run(&progress, cancel);
        if (batch.chosen()) return batch.run(cancel);
        if (farm.standalone() || farm.farmBake()) return farm.run(options, outStem, jsonPath, quiet, cancel);
        // Taken before the work, so that a second bake of the stem fails at once.
        const opal::StemLock lock{opal::AssetStem(outStem)};
        opal::BakeReport report;
        const opal::TranslucentAsset asset = opal::bakeAsset(options, &progress, cancel, &report);
        cancel.throwIfRequested();
        opal::writeBakedAsset(lock, asset, &report, options.applyTo);
        for (const std::string& w : report.warnings) std::fprintf(stderr, "opal-bake: warning: %s\n", w.c_str());
        if (!jsonPath.empty()) opal::writeBakeReport(jsonPath, options, report);
        if (!quiet) std::fprintf(stderr, "%s", opal::formatBakeSummary(outStem, report).c_str());
        return 0;
    } catch (const opal::Cancelled&) {
        std::fprintf(stderr, "opal-bake: interrupted; nothing was written\n");
        return 128 + (gSignal ? int(gSignal) : SIGINT);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "opal-bake: error: %s\n", e.what());
        return 1;
    }
}
