// `opal-bench compare ENGINE.exr REFERENCE.exr`: issue 13's accuracy figures
// (bench/image_accuracy.h) for two renders of one scene that opal-render wrote, the engine's
// and the exact reference's (`opal-render --reference`), so that any scene (the candle demo,
// an artist's shot) is measured the way `opal-bench accuracy` measures its own views:
//
//   --layer NAME     the RGB layer compared (default subsurface: the transfer's output;
//                    `color` adds the specular and emission, which both modes share)
//   --prim-id N      the pixels compared: those whose primId is N in both images
//                    (repeatable; default 0, the scene's first translucent prim)
//   --error-image P  the per-pixel luminance error as a PNG (bench/error_image.h)
//
// Prints the figures against the targets and, with --json, writes them. Exit 0 when
// measured (whether or not the targets are met), 1 on an unreadable or mismatched input,
// naming the file and what is wrong.
#include "bench/accuracy_json.h"
#include "bench/accuracy_targets.h"
#include "bench/error_image.h"
#include "bench/exr_layer.h"
#include "bench/image_accuracy.h"
#include "bench/subcommand.h"

#include "delegate/output/preview_writer.h"
#include "schema/error.h"
#include "schema/usd/atomic_file.h"

#include <CLI/CLI.hpp>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace opal::bench {

namespace {

struct Options {
    std::string engine, reference, layer = "subsurface", jsonFile, errorImage;
    std::vector<int> primIds = {0};
};

int run(const Options& o) {
    const ExrLayer engine = readExrLayer(o.engine, o.layer), reference = readExrLayer(o.reference, o.layer);
    const std::vector<std::uint8_t> mask = primMask(engine, reference, o.primIds);  // sizes checked
    const ImageAccuracy a = measureAccuracy(engine.rgb, reference.rgb, mask);
    const AccuracyTargets targets;
    const std::vector<std::string> missed = missedTargets(a, targets);
    std::printf("opal-bench compare: %s against %s, layer %s, %zu pixels (%zu bright enough for per-pixel figures)\n",
                o.engine.c_str(), o.reference.c_str(), o.layer.c_str(), a.pixels, a.measured);
    std::printf("  relative RMSE %.4f (target <= %g)\n", a.relativeRmse, targets.relativeRmse);
    std::printf("  luminance error median %.4f, p95 %.4f (target <= %g); darker half median %.4f, p95 %.4f\n",
                a.luminance.median, a.luminance.p95, targets.luminanceP95, a.darkerHalf.median, a.darkerHalf.p95);
    std::printf("  chromaticity error median %.4f, p95 %.4f (target <= %g)\n", a.chromaticity.median,
                a.chromaticity.p95, targets.chromaticityP95);
    std::printf("  negative pixels %.4f (deepest %.2e of the p99 luminance)\n", a.negativeFraction, a.deepestNegative);
    std::printf("  targets: %s\n", missed.empty() ? "all met" : "MISSED");
    for (const std::string& m : missed) std::printf("    %s\n", m.c_str());
    if (!o.errorImage.empty()) {
        writePreview(o.errorImage, luminanceErrorImage(engine.width, engine.height, engine.rgb, reference.rgb, mask));
        std::printf("wrote %s\n", o.errorImage.c_str());
    }
    if (!o.jsonFile.empty()) {
        Json j = {{"engine", o.engine}, {"reference", o.reference}, {"layer", o.layer}, {"prim_ids", o.primIds}};
        j.update(accuracyJson(a));
        j.update(Json{{"targets", targetsJson(targets)}, {"pass", missed.empty()}, {"missed", missed}});
        writeFileAtomically(o.jsonFile, j.dump(2) + "\n");
        std::printf("wrote %s\n", o.jsonFile.c_str());
    }
    return 0;
}

int runCompare(int argc, char** argv) {
    CLI::App app{"Issue 13's accuracy figures for an engine render against its exact reference render (two EXRs)",
                 "opal-bench compare"};
    Options o;
    app.add_option("engine", o.engine, "the engine's EXR (opal-render)")->required();
    app.add_option("reference", o.reference, "the reference's EXR (opal-render --reference)")->required();
    app.add_option("--layer", o.layer, "the RGB layer compared: subsurface, specular, emission, color")
        ->check(CLI::IsMember({"subsurface", "specular", "emission", "color"}))
        ->capture_default_str();
    app.add_option("--prim-id", o.primIds, "compare the pixels of this primId (repeatable)")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    app.add_option("--error-image", o.errorImage,
                   "also write the per-pixel luminance error as a PNG (black 0, white 5% or more; unmeasured blue)");
    app.add_option("--json", o.jsonFile, "also write the figures as JSON to this file");
    CLI11_PARSE(app, argc, argv);
    try {
        return run(o);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "opal-bench compare: %s\n", e.what());
        return 1;
    }
}

}  // namespace

Subcommand compareSubcommand() {
    return {"compare", "accuracy figures of an engine EXR against its reference EXR (any scene)", runCompare};
}

}  // namespace opal::bench
