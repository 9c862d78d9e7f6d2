// opal-bench accuracy: the relighting engine's image against the exact reference image of the
// same scene (bench/image_accuracy.h's figures, judged against issue 13's targets,
// bench/accuracy_targets.h). For each mesh and sample count the mesh is baked at the shipped
// defaults (bench/cached_bake.h; only the sample count differs, and bakes are cached), or a
// baked asset is read (--asset); then for each material (the asset's default, and the
// shortest and longest mean free path its editable range allows, bench/mean_free_path_ends.h)
// and each case, the view of `opal-bench relight`'s scene (bench/relight_scene.h) is rendered
// to convergence by two delegates, one with the engine and one with opal:reference (the exact
// gather over the same samples; the same E for the analytic lights, and for the dome the
// brute-force hemisphere integral of the map, docs/ARCHITECTURE.md#dome-reference), and
// compared on the subsurface AOV over the pixels that show the asset in both. The cases:
//   point        one point light (relight's key light), no dome
//   directional  one distant light shining from the point light's position, no dome
//   dome         the studio HDR dome alone
// It measures: the exit code is 0 whether or not the targets are met (1 for bad input or a
// failed bake or render), and a summary line counts the images that meet them.
#include "bench/accuracy_json.h"
#include "bench/accuracy_targets.h"
#include "bench/cached_bake.h"
#include "bench/error_image.h"
#include "bench/image_accuracy.h"
#include "bench/mean_free_path_ends.h"
#include "bench/relight_scene.h"
#include "bench/shared_assets.h"
#include "bench/subcommand.h"

#include "delegate/hd/render_to_convergence.h"
#include "delegate/output/image.h"
#include "delegate/output/preview_writer.h"
#include "delegate/render_delegate.h"
#include "schema/asset/asset_layer.h"
#include "schema/error.h"
#include "schema/usd/atomic_file.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace opal::bench {

namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 640, kHeight = 360;
const std::vector<std::string> kCases = {"point", "directional", "dome"};

struct Options {
    std::vector<std::string> meshes;
    std::vector<std::uint64_t> samples = {4096, 16384, 65536};
    double unitsPerMm = 1.0;  // for --mesh
    std::vector<fs::path> assets;
    std::vector<std::string> materials = kEndMaterials;
    std::vector<std::string> cases = kCases;
    fs::path env = studioDomeMap();
    fs::path outputDir;
    fs::path jsonFile;
};

// A mesh to bake: its label in the table, the bake input and its scale.
struct MeshSpec {
    std::string label;
    std::string input;
    double unitsPerMm = 1.0;
};

// One asset to measure: baked here (bake holds the bake's report) or read (--asset).
struct Subject {
    std::string label;
    std::string source;
    std::shared_ptr<const TranslucentAsset> asset;
    Json bake;
};

// The default meshes: the bunny (millimetres), Spot as a 100 mm figurine (as `opal-bench
// bake`: its 1.71-unit limit surface at 0.0171 units per mm) and the built-in candle.
std::vector<MeshSpec> defaultMeshes() {
    const fs::path meshes = sharedAssets() / "meshes";
    return {{"bunny", (meshes / "stanford-bunny_watertight_quartet.obj").string(), 1.0},
            {"spot", (meshes / "spot_control_mesh.obj").string(), 0.0171},
            {"candle", "builtin:candle", 1.0}};
}

std::vector<MeshSpec> requestedMeshes(const Options& options) {
    if (options.meshes.empty()) return options.assets.empty() ? defaultMeshes() : std::vector<MeshSpec>{};
    std::vector<MeshSpec> specs;
    for (const std::string& mesh : options.meshes) specs.push_back({bakeLabel(mesh), mesh, options.unitsPerMm});
    return specs;
}

bool exists(const MeshSpec& mesh) {
    std::error_code ec;
    return mesh.input.rfind("builtin:", 0) == 0 || fs::is_regular_file(mesh.input, ec);
}

fs::path bakeCache(const Options& options) {
    return options.outputDir.empty() ? fs::temp_directory_path() / "opal-bench-accuracy-bakes"
                                     : options.outputDir / "bakes";
}

Subject bakedSubject(const MeshSpec& mesh, std::uint64_t samples, const fs::path& cache) {
    BakeOptions bake;
    bake.input = mesh.input;
    bake.samples = samples;
    bake.unitsPerMm = mesh.unitsPerMm;
    const CachedBake baked = bakeOrReuse(bake, mesh.label, cache);
    std::printf("  %s %s (%s)\n", baked.reused ? "reusing" : "baked", baked.layer.c_str(), mesh.input.c_str());
    return {mesh.label, mesh.input, baked.asset, Json{{"layer", baked.layer.string()}, {"reused", baked.reused},
                                                      {"report", baked.report}}};
}

Subject readSubject(const fs::path& file) {
    std::vector<std::string> warnings;
    auto asset = std::make_shared<const TranslucentAsset>(readAsset(file, &warnings));
    for (const std::string& w : warnings) std::printf("  warning: %s\n", w.c_str());
    const CompressedTransfer& t = asset->transfer;
    return {file.stem().string(), fs::absolute(file).lexically_normal().string(), asset,
            Json{{"layer", fs::absolute(file).lexically_normal().string()},
                 {"keep", t.keepFraction},
                 {"energy", t.energyFraction},
                 {"source", asset->bake.source}}};
}

// The subsurface (RGB) and primId AOVs of one view, converged.
struct Render {
    std::vector<float> subsurface, primId;
    CommitStats totals;  // the engine's zeroed noise among them (docs/ARCHITECTURE.md#nonnegative-radiance)
};

RelightScene::Key keyOf(const std::string& lightCase) {
    if (lightCase == "directional") return RelightScene::Key::Distant;
    if (lightCase == "dome") return RelightScene::Key::None;
    return RelightScene::Key::Point;
}

Render render(const std::shared_ptr<const TranslucentAsset>& asset, const Material& material,
              const std::string& lightCase, const fs::path& env, bool reference) {
    OpalRenderDelegate delegate({{"opal:reference", reference}});
    RelightScene scene(asset, material, lightCase == "dome" ? env.string() : "", double(kWidth) / kHeight,
                       keyOf(lightCase));
    hd::RenderIndex index(delegate);
    scene.populate(index);
    index.sync();
    hd::RenderBuffer subsurface("/Buffers/subsurface"), primId("/Buffers/primId");
    const auto pass = delegate.createRenderPass(index);
    hd::renderToConvergence(delegate, *pass, {RelightScene::CameraPath, kWidth, kHeight},
                            {{"subsurface", &subsurface}, {"primId", &primId}});
    for (const std::string& w : delegate.takeWarnings()) std::printf("  warning: %s\n", w.c_str());
    return {{subsurface.data().begin(), subsurface.data().end()},
            {primId.data().begin(), primId.data().end()},
            delegate.totals()};
}

// The table's rows as printed while measuring, printed again whole at the end (bake
// progress comes between a run's rows).
struct Tally {
    std::size_t images = 0, passed = 0;
    std::vector<std::string> rows;
};

// One row of the table: the engine's and the reference's view of one material and case.
Json measureImage(const Subject& s, const std::string& materialName, const std::string& lightCase,
                  const Options& options, Tally& tally) {
    const Material material = materialNamed(materialName, *s.asset);
    const Render engine = render(s.asset, material, lightCase, options.env, false);
    const Render reference = render(s.asset, material, lightCase, options.env, true);
    std::vector<std::uint8_t> mask(engine.primId.size());
    for (std::size_t p = 0; p < mask.size(); ++p) mask[p] = engine.primId[p] >= 0.0f && reference.primId[p] >= 0.0f;
    const ImageAccuracy a = measureAccuracy(engine.subsurface, reference.subsurface, mask);
    const std::vector<std::string> missed = missedTargets(a, AccuracyTargets{});
    ++tally.images;
    tally.passed += missed.empty();
    char row[256];
    std::snprintf(row, sizeof row, "%-10s %7zu %-8s %-11s %7zu %9.4f %8.4f %8.4f %8.4f %8.4f %9.4f %9.1e %9.1e  %s",
                  s.label.c_str(), s.asset->samples.size(), materialName.c_str(), lightCase.c_str(), a.pixels,
                  a.relativeRmse, a.luminance.median, a.luminance.p95, a.darkerHalf.p95, a.chromaticity.p95,
                  a.negativeFraction, a.deepestNegative, engine.totals.deepestProjected,
                  missed.empty() ? "PASS" : "FAIL");
    tally.rows.push_back(row);
    std::printf("%s\n", row);
    std::fflush(stdout);
    Json j = {{"mesh", s.label},
              {"source", s.source},
              {"samples", s.asset->samples.size()},
              {"material", materialJson(materialName, material)},
              {"case", lightCase}};
    j.update(accuracyJson(a));
    j.update(Json{{"engine_zeroed_values", engine.totals.projectedValues},
              {"engine_deepest_zeroed", engine.totals.deepestProjected},
              {"pass", missed.empty()},
              {"missed", missed}});
    if (!options.outputDir.empty()) {
        const fs::path png = options.outputDir / (s.label + "-" + std::to_string(s.asset->samples.size()) + "-" +
                                                  materialName + "-" + lightCase + "-error.png");
        writePreview(png, luminanceErrorImage(kWidth, kHeight, engine.subsurface, reference.subsurface, mask));
        j["error_image"] = png.string();
    }
    return j;
}

// The cases this subject can show: the dome needs the map and the asset's environment transfer.
std::vector<std::string> casesFor(const Subject& s, const Options& options) {
    std::vector<std::string> cases;
    for (const std::string& c : options.cases) {
        std::error_code ec;
        if (c == "dome" && !fs::is_regular_file(options.env, ec)) {
            std::printf("  %s: no dome case: the map %s is not there (pass --env or set OPAL_SHARED_ASSETS)\n",
                        s.label.c_str(), options.env.c_str());
            continue;
        }
        if (c == "dome" && s.asset->environment.offsets.empty()) {
            std::printf("  %s: no dome case: the asset has no environment transfer\n", s.label.c_str());
            continue;
        }
        cases.push_back(c);
    }
    return cases;
}

void printHeader() {
    std::printf("\n%-10s %7s %-8s %-11s %7s %9s %8s %8s %8s %8s %9s %9s %9s  %s\n", "mesh", "samples", "material",
                "case", "pixels", "rel.RMSE", "Y med", "Y p95", "dark p95", "chr p95", "negative", "deepest", "zeroed",
                "targets");
}

void measureSubject(const Subject& s, const Options& options, Json& images, Tally& tally) {
    for (const std::string& materialName : options.materials)
        for (const std::string& lightCase : casesFor(s, options))
            images.push_back(measureImage(s, materialName, lightCase, options, tally));
}

int run(const Options& options) {
    const AccuracyTargets targets;
    std::printf("opal-bench accuracy: engine vs exact reference (opal:reference), subsurface AOV, %dx%d, per image; "
                "targets rel.RMSE <= %g, Y p95 <= %g, chr p95 <= %g, negative fraction <= %g\n",
                kWidth, kHeight, targets.relativeRmse, targets.luminanceP95, targets.chromaticityP95,
                targets.negativeFraction);
    if (!options.outputDir.empty()) fs::create_directories(options.outputDir);
    const fs::path cache = bakeCache(options);
    Json bakes = Json::array(), images = Json::array();
    Tally tally;
    bool failed = false;
    printHeader();
    // One asset in memory at a time: each is measured before the next is read or baked.
    const auto measure = [&](const Subject& s) {
        Json bake = s.bake;
        bake["mesh"] = s.label;
        bake["samples"] = s.asset->samples.size();
        bakes.push_back(bake);
        measureSubject(s, options, images, tally);
    };
    for (const fs::path& file : options.assets) measure(readSubject(file));
    for (const MeshSpec& mesh : requestedMeshes(options)) {
        if (!exists(mesh)) {
            if (options.meshes.empty()) {  // a default mesh: the shared assets may be elsewhere
                std::printf("skipping %s: %s not found (set OPAL_SHARED_ASSETS to the shared assets folder)\n",
                            mesh.label.c_str(), mesh.input.c_str());
            } else {
                std::fprintf(stderr, "opal-bench accuracy: --mesh %s: no such file\n", mesh.input.c_str());
                failed = true;
            }
            continue;
        }
        for (std::uint64_t samples : options.samples) {
            try {
                measure(bakedSubject(mesh, samples, cache));
            } catch (const std::exception& e) {
                std::fprintf(stderr, "opal-bench accuracy: %s\n", e.what());
                failed = true;
            }
        }
    }
    printHeader();
    for (const std::string& row : tally.rows) std::printf("%s\n", row.c_str());
    std::printf("\n%zu of %zu images meet every target%s\n", tally.passed, tally.images,
                tally.passed == tally.images ? "" : " (a measurement: the exit code does not depend on it)");
    if (!options.jsonFile.empty()) {
        const Json result = {{"resolution", {kWidth, kHeight}},
                             {"aov", "subsurface"},
                             {"targets", targetsJson(targets)},
                             {"images_passing", tally.passed},
                             {"images", tally.images},
                             {"bakes", bakes},
                             {"results", images}};
        writeFileAtomically(options.jsonFile, result.dump(2) + "\n");
        std::printf("wrote %s\n", options.jsonFile.c_str());
    }
    return failed ? 1 : 0;
}

int runAccuracyBench(int argc, char** argv) {
    CLI::App app{"The engine's image against the exact reference image, per mesh, sample count, material and light",
                 "opal-bench accuracy"};
    Options options;
    app.add_option("--mesh", options.meshes,
                   "meshes to bake at the shipped defaults (repeatable; a file or builtin:candle; default: the bunny, "
                   "Spot and the candle unless --asset is given)");
    app.add_option("--samples", options.samples, "sample counts to bake each mesh at (repeatable)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    app.add_option("--units-per-mm", options.unitsPerMm, "scene units per mm of the --mesh meshes")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    app.add_option("--asset", options.assets, "already baked assets (ASSET.usda) to measure too (repeatable)");
    app.add_option("--material", options.materials, kEndMaterialsHelp)
        ->check(CLI::IsMember(kEndMaterials))
        ->capture_default_str();
    app.add_option("--case", options.cases, "lighting cases (repeatable)")
        ->check(CLI::IsMember(kCases))
        ->capture_default_str();
    app.add_option("--env", options.env, "the dome's lat-long map (default: the studio map in $OPAL_SHARED_ASSETS)");
    app.add_option("-o,--output", options.outputDir,
                   "write an error image per row here, and cache the bakes in its bakes/ (default: no images, "
                   "bakes cached in the temporary folder)");
    app.add_option("--json", options.jsonFile, "also write every figure as JSON to this file");
    CLI11_PARSE(app, argc, argv);
    try {
        return run(options);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "opal-bench accuracy: %s\n", e.what());
        return 1;
    }
}

}  // namespace

Subcommand accuracySubcommand() {
    return {"accuracy", "the engine's image against the exact reference image", runAccuracyBench};
}

}  // namespace opal::bench
