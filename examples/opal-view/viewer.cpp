#include "examples/opal-view/viewer.h"

#include "delegate/hd/aov.h"
#include "delegate/output/exr_writer.h"
#include "examples/opal-view/color_panel.h"
#include "examples/opal-view/core/default_scene.h"
#include "examples/opal-view/light_panel.h"
#include "examples/opal-view/material_panel.h"
#include "examples/opal-view/screenshot.h"
#include "examples/opal-view/viewport_input.h"
#include "plugin/search_paths.h"
#include "schema/error.h"

#include <glad/gl.h>
#include <imgui.h>

#include <iostream>
#include <variant>

namespace opal::view {
namespace {

using Clock = std::chrono::steady_clock;
// While the picture is still refining, a new pass is shown at least this often even when
// the delegate's pass counter did not move (a restart may reuse a count).
constexpr auto RefineInterval = std::chrono::milliseconds(100);
constexpr float PanelWidth = 300.0f;

bool opensGivenScene(const ViewOptions& options, const std::vector<ScriptAction>& script) {
    return options.scene || script.empty() || script.front().kind != ActionKind::Load;
}

}  // namespace

Viewer::Viewer(const ViewOptions& options, std::vector<ScriptAction> script)
    : renderer_(loadRenderer(options.delegate, std::cerr)),
      window_(options.width, options.height, "opal-view"),
      imgui_(window_),
      display_(ColorConfig::fromEnvironment()),
      model_(*renderer_.delegate, window_.framebufferSize().first, window_.framebufferSize().second) {
    const bool openScene = opensGivenScene(options, script);
    if (!script.empty()) script_.emplace(std::move(script));
    if (openScene) open(options.scene ? *options.scene : defaultScene(executablePath()));
    lastFrame_ = Clock::now();
}

void Viewer::run() {
    while (!window_.closeRequested() && !quit_) frame();
}

void Viewer::open(const std::filesystem::path& file) {
    model_.open(file);
    for (const std::string& warning : model_.takeLoadWarnings()) std::cerr << "opal-view: warning: " << warning << '\n';
    window_.setTitle("opal-view - " + file.string());
    shown_ = {};
    shownSettled_ = false;
}

void Viewer::frame() {
    window_.pollEvents();
    const Clock::time_point now = Clock::now();
    hud_.frameMs = std::chrono::duration<double, std::milli>(now - lastFrame_).count();
    lastFrame_ = now;
    imgui_.beginFrame();
    const auto [width, height] = window_.framebufferSize();
    if (width > 0 && height > 0) model_.setViewport(width, height);
    if (model_.isOpen()) drawInterface();
    collectMessages();
    if (script_ && script_->step(*this)) script_.reset();
    model_.update();
    refreshPicture();
    glViewport(0, 0, width, height);
    picture_.draw();
    imgui_.render();
    if (screenshot_) {
        saveScreenshot(*screenshot_, width, height);
        std::cout << "opal-view: wrote " << screenshot_->string() << std::endl;
        screenshot_.reset();
    }
    window_.swapBuffers();
}

void Viewer::drawInterface() {
    handleViewportInput(model_);
    ImGui::SetNextWindowPos(ImVec2(10.0f, 10.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(PanelWidth, 0.0f), ImGuiCond_FirstUseEver);
    ImGui::Begin("Look");
    drawMaterialPanel(model_);
    drawLightPanel(model_);
    drawColorPanel(display_, settings_);
    ImGui::End();
    drawHud(model_, hud_);
}

void Viewer::collectMessages() {
    if (!model_.isOpen()) return;
    for (const std::string& message : model_.session().takeMessages()) {
        std::cerr << "opal-view: " << message << '\n';
        hud_.message = message;
        if (message.starts_with("error: ") && renderError_.empty()) renderError_ = message.substr(7);
    }
}

Viewer::PictureKey Viewer::pictureKey() const {
    const auto stats = model_.session().delegate().renderStats();
    const auto passes = stats.find("passes");
    const int* count = passes == stats.end() ? nullptr : std::get_if<int>(&passes->second);
    return {count ? *count : 0, model_.session().status().syncs, settings_.version};
}

void Viewer::refreshPicture() {
    if (!model_.isOpen()) return;
    // Both read before the buffer is: a settled session writes nothing more into it.
    const bool settled = model_.settled();
    const PictureKey key = pictureKey();
    const Clock::time_point now = Clock::now();
    if (key == shown_ && (settled ? shownSettled_ : now - lastPicture_ < RefineInterval)) return;
    const Image linear = mappedImage(model_.session().buffer(settings_.aov));
    picture_.upload(display_.toDisplay(linear, settings_.aov, settings_.exposure));
    shown_ = key;
    shownSettled_ = settled;
    lastPicture_ = now;
}

bool Viewer::pictureSettled() { return model_.settled() && shownSettled_ && pictureKey() == shown_; }

std::string Viewer::takeRenderError() {
    std::string error;
    error.swap(renderError_);
    return error;
}

void Viewer::setDisplayView(const std::string& display, const std::string& view) {
    display_.setDisplayView(display, view);
    ++settings_.version;
}

void Viewer::setExposure(double stops) {
    settings_.exposure = stops;
    ++settings_.version;
}

void Viewer::setAov(const std::string& aov) {
    if (!hd::findAov(aov)) throw Error("unknown AOV '" + aov + "' (AOVs: " + hd::aovNameList() + ")");
    settings_.aov = aov;
    ++settings_.version;
}

void Viewer::requestScreenshot(const std::filesystem::path& file) {
    if (file.extension() != ".png") throw Error("screenshot " + file.string() + ": the file must end in .png");
    const std::filesystem::path folder = std::filesystem::absolute(file).parent_path();
    if (!std::filesystem::is_directory(folder))
        throw Error("screenshot " + file.string() + ": the folder " + folder.string() + " does not exist");
    screenshot_ = file;
}

void Viewer::saveExr(const std::filesystem::path& file) {
    std::vector<std::string> warnings;
    const ColorSpaceIdentity space = display_.config().workingSpaceIdentity(&warnings);
    const ExrMetadata metadata = {
        {"scene", std::filesystem::absolute(model_.file()).lexically_normal().string()},
        {"alpha", "premultiplied: R, G, B are radiance times A (OpenEXR convention)"},
        {"viewer", "opal-view"}};
    writeExr(file, model_.session().buffers().exrLayers(), space, metadata, ExrOptions{}, &warnings);
    for (const std::string& warning : warnings) std::cerr << "opal-view: warning: " << warning << '\n';
    std::cout << "opal-view: wrote " << file.string() << std::endl;
}

}  // namespace opal::view
