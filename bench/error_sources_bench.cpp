// `opal-bench error-sources --asset A.usda`: which step a dome image's error against the
// exact reference comes from, measured per sample (before the vertices and pixels blend
// it), for the asset's default material and the two ends of its editable range
// (bench/mean_free_path_ends.h):
//
//   irradiance        the dome's E through the baked vectors (the engine's,
//                     MeshIrradiance::exactIrradiance) against the brute-force hemisphere
//                     integral (MeshIrradiance::referenceIrradiance)
//   transfer, dome    the engine's L against the exact gather of the engine's own E: the
//                     compressed transfer alone, under the dome's light, and split by
//                     step (bench/transfer_step_gathers.h): the profile basis alone
//                     (lossless, against the exact gather), step 1 (against lossless) and
//                     the rest, step 2 and the stored values (the engine against step 1)
//   transfer, uniform the same with E = 1 at every sample: the transfer's error without
//                     the light's contrast
//   whole             the engine's L against the exact gather of the reference E: what
//                     `opal-bench accuracy --case dome` sees, at the samples
//
// each as bench/image_accuracy.h's figures with a sample in place of a pixel (relative
// RMSE; per-sample luminance error over the samples whose reference is at least 1% of the
// 99th percentile, median and 95th percentile, and over the darker half of them;
// chromaticity). The dome is the map with the identity transform, as `opal-bench
// accuracy` lights it. Per material, three exact gathers, O(N) per output, and two replays,
// O(N K) per output (about 40 s in all at every one of 16,384 samples on 2 cores, minutes
// at 65,536: `--outputs M` measures M random samples).
// Findings: docs/ARCHITECTURE.md#compression.
#include "bench/accuracy_json.h"
#include "bench/dome_map.h"
#include "bench/image_accuracy.h"
#include "bench/mean_free_path_ends.h"
#include "bench/random_outputs.h"
#include "bench/shared_assets.h"
#include "bench/subcommand.h"
#include "bench/transfer_step_gathers.h"

#include "delegate/relight/mesh_irradiance.h"
#include "delegate/relight/reference_gather.h"
#include "delegate/relight/relight_engine.h"
#include "schema/asset/asset_layer.h"
#include "schema/error.h"
#include "schema/usd/atomic_file.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace opal::bench {

namespace {

namespace fs = std::filesystem;

struct Options {
    std::string asset, jsonFile;
    fs::path env = studioDomeMap();
    std::vector<std::string> materials = kEndMaterials;
    std::uint32_t keepMin = TransferSettings{}.minPerRow;
    std::size_t outputs = 0;  // random samples measured (0: every sample)
};

std::vector<float> copyOf(std::span<const float> values) { return {values.begin(), values.end()}; }

// values (samples x 3) at `outputs` (every sample when empty), outputs x 3.
std::vector<float> at(std::span<const float> values, std::span<const std::uint32_t> outputs) {
    if (outputs.empty()) return copyOf(values);
    std::vector<float> picked(3 * outputs.size());
    for (std::size_t j = 0; j < outputs.size(); ++j)
        std::copy_n(values.begin() + 3 * std::size_t(outputs[j]), 3, picked.begin() + 3 * j);
    return picked;
}

// The engine's L and E for the material under the given moments.
std::pair<std::vector<float>, std::vector<float>> relight(const std::shared_ptr<const TranslucentAsset>& asset,
                                                          const Material& material,
                                                          const IrradianceMoments& moments) {
    RelightEngine engine(asset);
    engine.setMaterial(material);
    engine.setIrradiance(moments);
    return {copyOf(engine.sampleRadiance()), copyOf(engine.sampleIrradiance())};
}

// E_0 = 1 at every sample and channel, the other moments 0: E = c_0(eta), the same everywhere.
IrradianceMoments uniformMoments(const IrradianceMoments& shape) {
    IrradianceMoments uniform(shape.samples, shape.terms, shape.basis);
    for (std::size_t i = 0; i < uniform.samples; ++i)
        for (int c = 0; c < 3; ++c) uniform.sample(i)[c] = 1.0f;
    return uniform;
}

void printRow(const std::string& material, const char* source, const ImageAccuracy& a) {
    std::printf("%-8s %-18s %9.4f %8.4f %8.4f %8.4f %8.4f\n", material.c_str(), source, a.relativeRmse,
                a.luminance.median, a.luminance.p95, a.darkerHalf.p95, a.chromaticity.p95);
    std::fflush(stdout);
}

Json measureMaterial(const std::shared_ptr<const TranslucentAsset>& asset, MeshIrradiance& dome,
                     const std::string& name, const TransferSettings& step1, std::span<const std::uint32_t> outputs) {
    const Material material = materialNamed(name, *asset);
    const std::vector<float> engineE = dome.exactIrradiance(material.eta);
    const std::vector<float> referenceE = dome.referenceIrradiance(material.eta);
    const auto [domeL, domeE] = relight(asset, material, dome.moments());
    const auto [uniformL, uniformE] = relight(asset, material, uniformMoments(dome.moments()));
    const std::vector<float> exactL = referenceGather(*asset, material, domeE, outputs);
    const std::vector<float> losslessL = losslessGather(*asset, material, domeE, outputs);
    const std::vector<float> step1L = step1Gather(*asset, material, domeE, step1, outputs);
    const std::vector<float> engineL = at(domeL, outputs);

    const std::pair<const char*, ImageAccuracy> sources[] = {
        {"irradiance", measureAccuracy(engineE, referenceE)},
        {"transfer_dome", measureAccuracy(engineL, exactL)},
        {"dome_basis", measureAccuracy(losslessL, exactL)},
        {"dome_step1", measureAccuracy(step1L, losslessL)},
        {"dome_step2_values", measureAccuracy(engineL, step1L)},
        {"transfer_uniform", measureAccuracy(at(uniformL, outputs), referenceGather(*asset, material, uniformE, outputs))},
        {"whole", measureAccuracy(engineL, referenceGather(*asset, material, referenceE, outputs))},
    };
    Json j = {{"material", materialJson(name, material)}};
    for (const auto& [source, a] : sources) {
        printRow(name, source, a);
        j[source] = accuracyJson(a);
    }
    return j;
}

int run(const Options& options) {
    std::vector<std::string> warnings;
    auto asset = std::make_shared<const TranslucentAsset>(readAsset(options.asset, &warnings));
    for (const std::string& w : warnings) std::printf("  warning: %s\n", w.c_str());
    if (asset->environment.offsets.empty())
        throw Error("asset '" + options.asset + "' has no environment transfer: nothing lights it as a dome");
    hd::LightDesc desc;
    desc.kind = hd::LightKind::Dome;
    desc.textureFile = options.env.string();
    const auto light =
        std::make_shared<const EnvironmentLight>(EnvironmentLight::fromDesc(readDomeMap(options.env), desc));
    MeshIrradiance dome(asset, Imath::M44d());
    dome.setLight(hd::SdfPath("/Dome"), light);

    const std::vector<std::uint32_t> outputs = randomOutputs(asset->samples.size(), options.outputs);
    std::printf("opal-bench error-sources: %s, %zu samples, dome %s; per-sample figures (bench/image_accuracy.h) at %zu "
                "of them (the dome's E at all); step 1 replayed at keep %g, keep-min %u\n",
                options.asset.c_str(), asset->samples.size(), options.env.c_str(),
                outputs.empty() ? asset->samples.size() : outputs.size(), asset->transfer.keepFraction, options.keepMin);
    std::printf("%-8s %-18s %9s %8s %8s %8s %8s\n", "material", "source", "rel.RMSE", "Y med", "Y p95", "dark p95",
                "chr p95");
    Json results = Json::array();
    TransferSettings step1;
    step1.keepFraction = asset->transfer.keepFraction;
    step1.minPerRow = options.keepMin;
    for (const std::string& name : options.materials)
        results.push_back(measureMaterial(asset, dome, name, step1, outputs));
    if (!options.jsonFile.empty()) {
        const Json j = {{"asset", options.asset},
                        {"env", options.env.string()},
                        {"samples", asset->samples.size()},
                        {"measured_outputs", outputs.empty() ? asset->samples.size() : outputs.size()},
                        {"step1_keep", step1.keepFraction},
                        {"step1_keep_min", step1.minPerRow},
                        {"results", results}};
        writeFileAtomically(options.jsonFile, j.dump(2) + "\n");
        std::printf("wrote %s\n", options.jsonFile.c_str());
    }
    return 0;
}

int runErrorSources(int argc, char** argv) {
    CLI::App app{"Per sample, which step a dome image's error comes from: the dome's irradiance or the compressed "
                 "transfer (under the dome, and under uniform light)",
                 "opal-bench error-sources"};
    Options options;
    app.add_option("--asset", options.asset, "the baked asset (ASSET.usda)")->required();
    app.add_option("--env", options.env, "the dome's lat-long map (default: the studio map in $OPAL_SHARED_ASSETS)");
    app.add_option("--material", options.materials, kEndMaterialsHelp)
        ->check(CLI::IsMember(kEndMaterials))
        ->capture_default_str();
    app.add_option("--keep-min", options.keepMin,
                   "the floor of step 1 the asset was baked with (opal-bake --keep-min; the asset does not record it)")
        ->capture_default_str();
    app.add_option("--outputs", options.outputs,
                   "measure the transfer at this many random samples (default: every sample; the replays cost O(N K) "
                   "per sample, minutes for all of 65,536)");
    app.add_option("--json", options.jsonFile, "also write every figure as JSON to this file");
    CLI11_PARSE(app, argc, argv);
    try {
        return run(options);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "opal-bench error-sources: %s\n", e.what());
        return 1;
    }
}

}  // namespace

Subcommand errorSourcesSubcommand() {
    return {"error-sources", "which step a dome image's error comes from, per sample", runErrorSources};
}

}  // namespace opal::bench
