// opal-view: the look-development viewer. Opens a scene layer or a baked asset layer (with
// no argument, the candle of scripts/run-main) in a window and relights it as the material,
// the lights and the camera are edited. --screenshot and --script drive it unattended.
// Exit codes: 0 success, 1 error (a script's names its FILE:LINE), 2 bad command line.
#include "examples/opal-view/viewer.h"
#include "examples/scene/render_settings_prim.h"
#include "schema/error.h"

#include <CLI/CLI.hpp>

#include <iostream>

namespace {

constexpr int ExitError = 1;
constexpr int ExitUsage = 2;

void defineOptions(CLI::App& app, opal::view::ViewOptions& options, std::string& size) {
    app.add_option("scene", options.scene, "Scene layer or baked asset layer (.usda); default: the candle")
        ->check(CLI::ExistingFile);
    app.add_option("--screenshot", options.screenshot,
                   "Render to convergence, save the window (interface included) to this PNG and exit");
    app.add_option("--script", options.script, "Run the actions in this file, one per line")->check(CLI::ExistingFile);
    app.add_option("--size", size, "Window size WIDTHxHEIGHT (default 1280x720)");
    app.add_option("--delegate", options.delegate,
                   "Renderer plugin type to render with (default: the registry's default; the picker, "
                   "View > Render delegates, lists them)");
}

// The script's actions, then --screenshot's: wait for convergence, save, quit.
std::vector<opal::view::ScriptAction> actionsOf(const opal::view::ViewOptions& options) {
    using opal::view::ActionKind;
    std::vector<opal::view::ScriptAction> actions;
    if (options.script) actions = opal::view::readScript(*options.script);
    if (options.screenshot) {
        actions.push_back({ActionKind::Wait, "--screenshot", {}, {}});
        actions.push_back({ActionKind::Screenshot, "--screenshot", {options.screenshot->string()}, {}});
        actions.push_back({ActionKind::Quit, "--screenshot", {}, {}});
    }
    return actions;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"opal-view: look development for baked translucent assets"};
    opal::view::ViewOptions options;
    std::string size;
    defineOptions(app, options, size);
    try {
        app.parse(argc, argv);
        if (!size.empty()) {
            const opal::scene::Resolution resolution = opal::scene::parseResolution(size);
            options.width = resolution.width;
            options.height = resolution.height;
        }
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return ExitUsage;
    } catch (const opal::Error& e) {  // --size
        std::cerr << "opal-view: --size: " << e.what() << "\nRun with --help for more information.\n";
        return ExitUsage;
    }
    try {
        opal::view::Viewer viewer(options, actionsOf(options));
        viewer.run();
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "opal-view: error: " << e.what() << '\n';
        return ExitError;
    }
}
