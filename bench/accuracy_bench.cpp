// opal-bench accuracy: the relighting engine's image against the exact reference image of the
// same scene (bench/image_accuracy.h's figures). This first part covers baked assets under one
// point light: the key-light view of `opal-bench relight`'s scene (bench/relight_scene.h) at
// the asset's default material, rendered to convergence by two delegates, one with the engine
// and one with opal:reference (the exact dipole gather over the same samples and E), compared
// on the subsurface AOV over the pixels that show the asset in both. Baking meshes at chosen
// sample counts, the directional and dome cases and the material range come with issue 13.
#include "bench/image_accuracy.h"
#include "bench/relight_scene.h"
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

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace opal::bench {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

constexpr int kWidth = 640, kHeight = 360;

struct Options {
    std::vector<fs::path> assets;
    fs::path outputDir;
    fs::path jsonFile;
};

// The subsurface (RGB) and primId AOVs of the key-light view, converged.
struct Render {
    std::vector<float> subsurface, primId;
};

Render render(const std::shared_ptr<const TranslucentAsset>& asset, bool reference) {
    OpalRenderDelegate delegate({{"opal:reference", reference}});
    RelightScene scene(asset, asset->defaultMaterial, "", double(kWidth) / kHeight);
    hd::RenderIndex index(delegate);
    scene.populate(index);
    index.sync();
    hd::RenderBuffer subsurface("/Buffers/subsurface"), primId("/Buffers/primId");
    const auto pass = delegate.createRenderPass(index);
    hd::renderToConvergence(delegate, *pass, {RelightScene::CameraPath, kWidth, kHeight},
                            {{"subsurface", &subsurface}, {"primId", &primId}});
    return {{subsurface.data().begin(), subsurface.data().end()}, {primId.data().begin(), primId.data().end()}};
}

// |Y(a) - Y(b)| / Y(b) as grey, 0 -> black and 5% or more -> white; pixels off the asset blue.
Image errorImage(const Render& engine, const Render& reference, const std::vector<std::uint8_t>& mask) {
    Image image(kWidth, kHeight, 3);
    for (std::size_t p = 0; p < mask.size(); ++p) {
        float* out = image.pixels().data() + 3 * p;
        if (!mask[p]) {
            out[0] = 0.05f, out[1] = 0.1f, out[2] = 0.3f;
            continue;
        }
        double ya = 0.0, yb = 0.0;
        for (int c = 0; c < 3; ++c) {
            ya += kAcescgLuminance[c] * engine.subsurface[3 * p + c];
            yb += kAcescgLuminance[c] * reference.subsurface[3 * p + c];
        }
        const float grey = yb > 0.0 ? float(std::min(1.0, std::abs(ya - yb) / yb / 0.05)) : 1.0f;
        out[0] = out[1] = out[2] = grey;
    }
    return image;
}

Json percentilesJson(const Percentiles& p) { return {{"median", p.median}, {"p95", p.p95}}; }

Json measureAsset(const fs::path& file, const Options& options) {
    std::vector<std::string> warnings;
    auto asset = std::make_shared<const TranslucentAsset>(readAsset(file, &warnings));
    for (const std::string& w : warnings) std::printf("  warning: %s\n", w.c_str());
    const Render engine = render(asset, false), reference = render(asset, true);
    std::vector<std::uint8_t> mask(engine.primId.size());
    for (std::size_t p = 0; p < mask.size(); ++p) mask[p] = engine.primId[p] >= 0.0f && reference.primId[p] >= 0.0f;
    const ImageAccuracy a = measureAccuracy(engine.subsurface, reference.subsurface, mask);
    std::printf("%-28s %8zu %7zu %9.4f %8.4f %8.4f %8.4f %8.4f %8.4f %9.4f\n", file.filename().c_str(),
                asset->samples.size(), a.pixels, a.relativeRmse, a.luminance.median, a.luminance.p95,
                a.darkerHalf.median, a.darkerHalf.p95, a.chromaticity.p95, a.negativeFraction);
    Json j = {{"asset", fs::absolute(file).lexically_normal().string()},
              {"samples", asset->samples.size()},
              {"case", "point"},
              {"resolution", std::to_string(kWidth) + "x" + std::to_string(kHeight)},
              {"pixels", a.pixels},
              {"measured_pixels", a.measured},
              {"relative_rmse", a.relativeRmse},
              {"luminance_error", percentilesJson(a.luminance)},
              {"darker_half_luminance_error", percentilesJson(a.darkerHalf)},
              {"chromaticity_error", percentilesJson(a.chromaticity)},
              {"negative_fraction", a.negativeFraction}};
    if (!options.outputDir.empty()) {
        fs::create_directories(options.outputDir);
        const fs::path png = options.outputDir / (file.stem().string() + "-point-error.png");
        writePreview(png, errorImage(engine, reference, mask));
        j["error_image"] = png.string();
    }
    return j;
}

int run(const Options& options) {
    std::printf("opal-bench accuracy: engine vs exact reference, subsurface AOV, %dx%d, one point light, the "
                "asset's default material\n\n",
                kWidth, kHeight);
    std::printf("%-28s %8s %7s %9s %8s %8s %8s %8s %8s %9s\n", "asset", "samples", "pixels", "rel.RMSE", "Y med",
                "Y p95", "dark med", "dark p95", "chr p95", "negative");
    Json results = Json::array();
    for (const fs::path& asset : options.assets) results.push_back(measureAsset(asset, options));
    if (!options.jsonFile.empty()) {
        writeFileAtomically(options.jsonFile, Json{{"cases", results}}.dump(2) + "\n");
        std::printf("\nwrote %s\n", options.jsonFile.c_str());
    }
    return 0;
}

int runAccuracyBench(int argc, char** argv) {
    CLI::App app{"The engine's image against the exact reference image (point light, baked assets)",
                 "opal-bench accuracy"};
    Options options;
    app.add_option("--asset", options.assets, "baked assets (ASSET.usda), repeatable")->required();
    app.add_option("-o,--output", options.outputDir, "write an error image per asset here");
    app.add_option("--json", options.jsonFile, "also write the results as JSON to this file");
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
