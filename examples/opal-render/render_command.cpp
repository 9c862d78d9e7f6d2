#include "examples/opal-render/render_command.h"

#include "delegate/output/color_config.h"
#include "delegate/output/display_transform.h"
#include "delegate/hd/render_index.h"
#include "delegate/hd/render_to_convergence.h"
#include "examples/opal-render/aov_buffers.h"
#include "examples/opal-render/frame_files.h"
#include "examples/opal-render/frame_range.h"
#include "examples/opal-render/stage_timer.h"
#include "examples/scene/material_override.h"
#include "examples/scene/render_setup.h"
#include "examples/scene/scene_reader.h"
#include "examples/scene/usda_scene_source.h"
#include "plugin/plugin_registry.h"
#include "plugin/search_paths.h"
#include "schema/error.h"

namespace opal::render {
namespace {

// What the preview goes through; built before rendering so a bad --display fails early.
std::optional<DisplayTransform> previewTransform(const ColorConfig& config, const RenderOptions& options) {
    if (!options.preview) return std::nullopt;
    const std::string display = options.display.value_or(config.defaultDisplay());
    const std::string view = options.view.value_or(config.defaultView(display));
    return DisplayTransform(config, display, view);
}

// The config the render delegate works in: the scene's opal:ocioConfig when it sets one
// (DELEGATE.md), else $OCIO or Opal's own, so that the files describe the delegate's colors.
ColorConfig outputColorConfig(const scene::Scene& scene) {
    if (!scene.renderSettings) return ColorConfig::fromEnvironment();
    for (const scene::DelegateSetting& setting : scene.renderSettings->delegateSettings) {
        const auto* file = std::get_if<std::string>(&setting.value);
        if (setting.name == "opal:ocioConfig" && file && !file->empty()) return ColorConfig::fromFile(*file);
    }
    return ColorConfig::fromEnvironment();
}

scene::Scene loadScene(const RenderOptions& options, scene::AssetCache& assets, std::ostream& warnings) {
    scene::Scene scene = scene::readScene(options.scene, assets);
    if (options.material) scene::overrideMaterials(scene, *options.material);
    for (const std::string& warning : scene.warnings) warnings << "opal-render: warning: " << warning << '\n';
    return scene;
}

RendererPluginHandle findRenderer(const RenderOptions& options, std::ostream& warnings) {
    const PluginRegistry registry(hostSearchPaths(executablePath()));
    for (const std::string& problem : registry.problems()) warnings << "opal-render: warning: " << problem << '\n';
    return options.delegate ? registry.createRendererPlugin(*options.delegate) : registry.defaultRendererPlugin();
}

RenderDelegateHandle createDelegate(const RendererPluginHandle& plugin, const scene::Scene& scene,
                                    const RenderOptions& options) {
    RenderDelegateHandle delegate = plugin.createRenderDelegate();
    if (scene.renderSettings) scene::applyRenderSettings(*scene.renderSettings, *delegate);
    if (options.reference) delegate->setRenderSetting("opal:reference", true);
    return delegate;
}

// The scene in a render index on one delegate, rendered at any scene time: between frames
// only what the time changes (flickering and animated lights, animated cameras and
// xforms) is synced again.
class SceneRender {
public:
    SceneRender(hd::RenderDelegate& delegate, scene::Scene scene, scene::AssetCache& assets)
        : delegate_(delegate), assets_(assets), source_(std::move(scene)), index_(delegate) {
        source_.populate(index_);
    }

    void render(double seconds, const scene::RenderSetup& setup, const AovBuffers& buffers, StageTimer& timer,
                std::ostream& warnings) {
        source_.setTime(seconds, index_, assets_);  // its errors name the scene file already
        try {
            index_.sync();
        } catch (const Error& e) {
            throw Error(source_.scene().file.string() + ": " + e.what());
        }
        timer.lap("sync");
        if (!pass_) pass_ = delegate_.createRenderPass(index_);
        hd::RenderPassState state;
        state.camera = setup.camera;
        state.width = setup.resolution.width;
        state.height = setup.resolution.height;
        hd::renderToConvergence(delegate_, *pass_, state, buffers.bindings());
        for (const std::string& warning : delegate_.takeWarnings())
            warnings << "opal-render: warning: " << warning << '\n';
        timer.lap("render");
    }

private:
    hd::RenderDelegate& delegate_;
    scene::AssetCache& assets_;
    scene::UsdaSceneSource source_;
    hd::RenderIndex index_;
    std::unique_ptr<hd::RenderPass> pass_;
};

// The delegate's render settings as the delegate holds them ("opal:tileSize" ->
// "opal/tileSize" in the header), then what describes the run.
ExrMetadata frameMetadata(const RenderOptions& options, const scene::RenderSetup& setup, const ColorConfig& config,
                          const RendererPluginHandle& plugin, const hd::RenderDelegate& delegate, double seconds) {
    ExrMetadata metadata;
    for (const auto& [key, value] : delegate.renderSettings()) {
        const std::string name = key.starts_with("opal:") ? key.substr(5) : key;
        if (const bool* b = std::get_if<bool>(&value)) metadata.emplace_back(name, int(*b));
        if (const int* i = std::get_if<int>(&value)) metadata.emplace_back(name, *i);
        if (const double* d = std::get_if<double>(&value)) metadata.emplace_back(name, float(*d));
        if (const std::string* t = std::get_if<std::string>(&value)) metadata.emplace_back(name, *t);
    }
    // OpenEXR's convention, said in the file: colour is premultiplied by alpha.
    metadata.emplace_back("alpha", "premultiplied: R, G, B are radiance times A (OpenEXR convention)");
    metadata.emplace_back("scene", std::filesystem::absolute(options.scene).lexically_normal().string());
    metadata.emplace_back("camera", setup.camera);
    metadata.emplace_back("time", float(seconds));  // the scene time, seconds
    metadata.emplace_back("resolution",
                          std::to_string(setup.resolution.width) + "x" + std::to_string(setup.resolution.height));
    metadata.emplace_back("material", options.material.value_or("scene"));
    metadata.emplace_back("delegate", plugin.info().displayName + " (" + plugin.info().typeName + ")");
    // Which file the colours are in: $OCIO, the scene's, or the one shipped with this program.
    metadata.emplace_back("colorConfig", std::filesystem::absolute(config.file()).lexically_normal().string());
    return metadata;
}

std::string summary(const RenderOptions& options, const scene::RenderSetup& setup, const RendererPluginHandle& plugin,
                    const StageTimer& timer, std::size_t frames) {
    const std::string what = options.frames ? std::to_string(frames) + " frames " +
                                                  numberedPath(options.output, options.frames->start).string() + ".."
                                            : options.output.string();
    return "opal-render: " + what + " " + std::to_string(setup.resolution.width) + "x" +
           std::to_string(setup.resolution.height) + " through <" + setup.camera + "> with " +
           plugin.info().displayName + ": " + timer.summary();
}

}  // namespace

std::string renderScene(const RenderOptions& options, std::ostream& warnings) {
    StageTimer timer;
    // Each frame's time in seconds and its files, all checked before any work.
    std::vector<std::pair<double, FrameFiles>> frames;
    scene::AssetCache assets;
    scene::Scene scene = loadScene(options, assets, warnings);
    if (!options.frames) frames.push_back({options.time, FrameFiles{options.output, options.preview}});
    for (const int frame : options.frames ? framesOf(*options.frames) : std::vector<int>{}) {
        std::optional<std::filesystem::path> preview;
        if (options.preview) preview = numberedPath(*options.preview, frame);
        frames.push_back({frame / scene.timeCodesPerSecond, FrameFiles{numberedPath(options.output, frame), preview}});
    }
    for (const auto& [seconds, files] : frames) checkFrameFiles(files);
    const scene::RenderSetup setup = scene::chooseRenderSetup(scene, {options.camera, options.resolution});
    const ColorConfig config = outputColorConfig(scene);
    const std::optional<DisplayTransform> display = previewTransform(config, options);
    timer.lap("load");

    const RendererPluginHandle plugin = findRenderer(options, warnings);
    const RenderDelegateHandle delegate = createDelegate(plugin, scene, options);
    timer.lap("delegate");

    const AovBuffers buffers(options.aovs, display.has_value());
    SceneRender render(*delegate, std::move(scene), assets);
    for (const auto& [seconds, files] : frames) {
        render.render(seconds, setup, buffers, timer, warnings);
        std::vector<std::string> writeWarnings;
        FrameContent content{buffers.exrLayers(), config.workingSpaceIdentity(&writeWarnings),
                             frameMetadata(options, setup, config, plugin, *delegate, seconds), ExrOptions{}, std::nullopt};
        if (options.floatPixels) content.options.colorPixelType = ExrPixelType::Float;
        if (display) content.previewImage = display->apply(buffers.color());
        writeFrameFiles(files, content, &writeWarnings);
        for (const std::string& warning : writeWarnings) warnings << "opal-render: warning: " << warning << '\n';
        timer.lap("write");
    }
    return summary(options, setup, plugin, timer, frames.size());
}

}  // namespace opal::render
