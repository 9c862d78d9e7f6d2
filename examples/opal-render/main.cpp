// opal-render: renders a scene layer (examples/SCENES.md) through a render delegate found by
// the plugin registry into a scene-linear multi-layer EXR, plus an optional display-referred
// preview. Exit codes: 0 success, 1 error (nothing written), 2 bad command line.
// --list-delegates prints what the plugin registry finds instead, and exits 0.
#include "delegate/hd/aov.h"
#include "examples/opal-render/frame_range.h"
#include "examples/opal-render/render_command.h"
#include "examples/scene/scene_material.h"
#include "plugin/plugin_listing.h"
#include "plugin/search_paths.h"
#include "schema/error.h"

#include <CLI/CLI.hpp>

#include <iostream>

namespace {

constexpr int ExitError = 1;
constexpr int ExitUsage = 2;

// hd/aov.h's table: the AOVs every Opal delegate renders.
std::vector<std::string> aovNames() {
    std::vector<std::string> names;
    for (const opal::hd::AovDescriptor& aov : opal::hd::aovTable()) names.push_back(aov.name);
    return names;
}

std::vector<std::string> presetNames() {
    std::vector<std::string> names;
    for (const opal::NamedMaterial& preset : opal::jensenPresets()) names.emplace_back(preset.name);
    return names;
}

void defineOptions(CLI::App& app, opal::render::RenderOptions& options, std::string& resolution,
                   std::string& frameRange, int& frameStep) {
    app.add_option("scene", options.scene, "Scene layer (.usda) to render")->required()->check(CLI::ExistingFile);
    app.add_option("-o,--output", options.output, "Scene-linear multi-layer EXR to write")->required();
    auto* preview = app.add_option("--preview", options.preview, "Display-referred 8-bit preview (.png, .jpg)");
    app.add_option("--resolution", resolution, "Image size WIDTHxHEIGHT (default: the scene's RenderSettings)");
    app.add_option("--aov", options.aovs, "AOVs to write (default: all)")->check(CLI::IsMember(aovNames()));
    app.add_option("--display", options.display, "OCIO display for the preview")->needs(preview);
    app.add_option("--view", options.view, "OCIO view for the preview")->needs(preview);
    app.add_option("--material", options.material, "Give every mesh this preset material")
        ->check(CLI::IsMember(presetNames()));
    app.add_flag("--reference", options.reference, "Render with the exact dipole gather (opal:reference)");
    app.add_flag("--float", options.floatPixels, "Write 32-bit float color layers (default: half)");
    app.add_option("--camera", options.camera, "Camera prim path (default: the scene's)");
    app.add_option("--delegate", options.delegate, "Renderer plugin type (default: the registry's default)");
    // Like --help, it ends parsing at once, so the scene and -o are not required with it.
    app.add_flag_callback("--list-delegates", [] { throw CLI::Success(); },
                          "List the renderer plugins found (and skipped manifests) and exit")
        ->trigger_on_parse();
    auto* time = app.add_option("--time", options.time,
                                "Scene time in seconds for time-varying lights (flicker; default 0)")
                     ->check(CLI::Range(-1.0e9, 1.0e9));
    auto* frames = app.add_option("--frames", frameRange,
                                  "Render time codes START:END (the layer's timeCodesPerSecond) to OUT.####.exr")
                       ->excludes(time);
    app.add_option("--step", frameStep, "Time codes between frames of --frames (default 1)")->needs(frames);
}

// --list-delegates: every detail of what the registry finds from this program.
int listDelegates() {
    try {
        std::cout << opal::pluginListing(opal::PluginRegistry(opal::hostSearchPaths(opal::executablePath())),
                                         {.current = {}, .details = true});
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "opal-render: error: " << e.what() << '\n';
        return ExitError;
    }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"opal-render: render a USDA scene of baked translucent assets to EXR"};
    opal::render::RenderOptions options;
    std::string resolution, frameRange;
    int frameStep = 1;
    defineOptions(app, options, resolution, frameRange, frameStep);
    try {
        app.parse(argc, argv);
        if (!resolution.empty()) options.resolution = opal::scene::parseResolution(resolution);
        if (!frameRange.empty()) options.frames = opal::render::parseFrameRange(frameRange, frameStep);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::Success&) {  // --list-delegates
        return listDelegates();
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return ExitUsage;
    } catch (const opal::Error& e) {  // --resolution, --frames
        std::cerr << "opal-render: " << e.what() << "\nRun with --help for more information.\n";
        return ExitUsage;
    }
    try {
        std::cout << opal::render::renderScene(options, std::cerr) << std::endl;
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "opal-render: error: " << e.what() << '\n';
        return ExitError;
    }
}
