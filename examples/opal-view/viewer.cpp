#include "examples/opal-view/viewer.h"

#include "delegate/hd/aov.h"
#include "delegate/output/exr_writer.h"
#include "delegate/output/preview_writer.h"
#include "examples/opal-view/color_panel.h"
#include "examples/opal-view/delegate_panels.h"
#include "examples/opal-view/delegate_picker.h"
#include "examples/opal-view/keyboard_help.h"
#include "examples/opal-view/probe_tooltip.h"
#include "examples/opal-view/core/default_scene.h"
#include "examples/opal-view/core/pixel_probe.h"
#include "examples/opal-view/camera_panel.h"
#include "examples/opal-view/light_gizmo_overlay.h"
#include "examples/opal-view/light_panel.h"
#include "examples/opal-view/material_panel.h"
#include "examples/opal-view/screenshot.h"
#include "examples/opal-view/viewport_input.h"
#include "plugin/plugin_listing.h"
#include "plugin/search_paths.h"
#include "schema/error.h"

#include <glad/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <iostream>
#include <variant>

namespace opal::view {
namespace {

using Clock = std::chrono::steady_clock;
// While the picture is still refining, a new pass is converted at most this often (the
// conversion competes with the renderer for the CPU), except the first pass of a new
// edit, which is converted as soon as the converter is free.
constexpr auto RefineInterval = std::chrono::milliseconds(500);
constexpr float PanelWidth = 300.0f;
constexpr float HudHeight = 70.0f;  // the heads-up line and a message under it
// ImGui sizes a window it shows for the first time over its first frames (drawn from the
// second): a script waits this many before the window counts as showing a panel.
constexpr int PanelLayoutFrames = 3;

// The config the delegate converts dome textures with (a scene may set opal:ocioConfig,
// DELEGATE.md), so that the picture is shown in the space the renderer worked in, as
// opal-render's preview is; $OCIO or Opal's own otherwise.
ColorConfig delegateColorConfig(const hd::RenderDelegate& delegate) {
    const std::map<hd::Token, hd::Value> settings = delegate.renderSettings();
    const auto setting = settings.find("opal:ocioConfig");
    const std::string* file = setting == settings.end() ? nullptr : std::get_if<std::string>(&setting->second);
    return file && !file->empty() ? ColorConfig::fromFile(*file) : ColorConfig::fromEnvironment();
}

// A dragged control shows a draft of each edit first (one ray per 4 x 4 pixels, converted
// at that resolution too), when the delegate has Opal's setting for it; the picture it
// converges to is the same. Returns the block (1: none).
constexpr int DraftBlock = 4;

int useDraftPictures(hd::RenderDelegate& delegate) {
    for (const hd::RenderSettingDescriptor& setting : delegate.renderSettingDescriptors())
        if (setting.key == "opal:draftBlock") {
            delegate.setRenderSetting(setting.key, DraftBlock);
            return DraftBlock;
        }
    return 1;
}

// Mesa's software rasterizers run a shader on the CPU cores the renderer uses, and ran
// OCIO's ACES view slower than OCIO's own CPU code (350-500 ms a 1280 x 720 frame on the
// interface thread, against 280 ms on the converter's, under Xvfb on two cores): there,
// the converter thread keeps the transform.
bool softwareOpenGl() {
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const std::string name = renderer ? renderer : "";
    return name.find("llvmpipe") != std::string::npos || name.find("softpipe") != std::string::npos ||
           name.find("swrast") != std::string::npos;
}

bool opensGivenScene(const ViewOptions& options, const std::vector<ScriptAction>& script) {
    return options.scene || script.empty() || script.front().kind != ActionKind::Load;
}

}  // namespace

Viewer::Viewer(const ViewOptions& options, std::vector<ScriptAction> script)
    : registry_(hostRegistry(std::cerr)),
      renderer_(loadRenderer(registry_, options.delegate)),
      window_(options.width, options.height, "opal-view"),
      imgui_(window_),
      display_(ColorConfig::fromEnvironment()),
      recent_(recentFilesPath()),
      model_(*renderer_.delegate, window_.framebufferSize().first, window_.framebufferSize().second),
      converter_(display_.config()) {
    if (!recent_.warning().empty()) std::cerr << "opal-view: warning: " << recent_.warning() << '\n';
    draftBlock_ = useDraftPictures(*renderer_.delegate);
    softwareOpenGl_ = softwareOpenGl();
    if (softwareOpenGl_) gpuDisplayError_ = "the OpenGL renderer is software";
    const bool openScene = opensGivenScene(options, script);
    model_.setRenderedAovs({"color"});
    if (!script.empty()) script_.emplace(std::move(script));
    if (openScene) open(options.scene ? *options.scene : defaultScene(executablePath()));
    lastFrame_ = Clock::now();
}

void Viewer::run() {
    while (!window_.closeRequested() && !quit_) frame();
}

void Viewer::open(const std::filesystem::path& file) {
    converter_.drain();  // it may be reading the open session's buffer
    converter_.take();
    if (reference_) reference_->drain();
    model_.open(file);
    const ColorConfig config = adoptDelegateConfig();
    // Whatever the config: the new scene's first reference picture may carry the same tag
    // as the old scene's last one.
    if (reference_) reference_->reset(config);
    for (const std::string& warning : model_.takeLoadWarnings()) std::cerr << "opal-view: warning: " << warning << '\n';
    updateTitle();
    requested_ = shown_ = {};
    shownImage_ = {};
    shownImageStale_ = false;
    try {
        recent_.add(file);
    } catch (const Error& e) {  // the scene is open: a list that cannot be kept is no reason to fail
        std::cerr << "opal-view: warning: " << e.what() << '\n';
    }
    shownApplied_ = 0;
}

ColorConfig Viewer::adoptDelegateConfig() {
    const ColorConfig config = delegateColorConfig(*renderer_.delegate);
    if (config.file() != display_.config().file()) {
        display_ = DisplayPicture(config);
        converter_.setConfig(config);
        ++settings_.version;
    }
    return config;
}

void Viewer::useDelegate(const std::string& typeName) {
    const RendererPluginInfo& info = registry_.requireRendererPlugin(typeName);
    if (info.typeName == renderer_.plugin.info().typeName) return;
    LoadedRenderer next = loadRenderer(registry_, info.typeName);  // the old one renders on meanwhile
    if (wipe_.on) setWipe(false, std::nullopt);
    converter_.drain();  // it may be reading the old session's buffer
    converter_.take();
    const int draftBlock = useDraftPictures(*next.delegate);
    try {
        model_.useDelegate(*next.delegate);
    } catch (const std::exception&) {
        model_.useDelegate(*renderer_.delegate);  // the scene renders as it did
        throw;
    }
    referenceDelegate_.reset();  // the wipe's, of the old plugin
    renderer_ = std::move(next);  // the old delegate goes, its sessions gone already
    draftBlock_ = draftBlock;
    adoptDelegateConfig();
    if (model_.isOpen() && !model_.session().renders(settings_.aov)) settings_.aov = "color";
    ++settings_.version;
    settingsProblem_.clear();
    requested_ = shown_ = {};
    shownApplied_ = 0;
    hud_.message = "renderer: " + renderer_.plugin.info().displayName;
}

std::string Viewer::delegateListing() {
    return pluginListing(registry_, {.current = renderer_.plugin.info().typeName});
}

void Viewer::carryOutDelegateChoice() {
    if (!chosenDelegate_) return;
    const std::string chosen = *std::exchange(chosenDelegate_, std::nullopt);
    try {
        useDelegate(chosen);
    } catch (const std::exception& e) {
        hud_.message = std::string("error: ") + e.what();
        std::cerr << "opal-view: " << hud_.message << '\n';
    }
}

void Viewer::frame() {
    window_.pollEvents();
    openDropped();
    const Clock::time_point now = Clock::now();
    hud_.frameMs = std::chrono::duration<double, std::milli>(now - lastFrame_).count();
    hud_.drawMs = std::max(0.0, hud_.frameMs - std::chrono::duration<double, std::milli>(lastWait_).count());
    lastFrame_ = now;
    imgui_.beginFrame();
    const auto [width, height] = window_.framebufferSize();
    if (width > 0 && height > 0) model_.setViewport(width, height);
    if (model_.isOpen()) drawInterface();
    carryOutDelegateChoice();
    ++framesSincePanels_;
    collectMessages();
    if (script_ && script_->step(*this)) script_.reset();
    updateTitle();
    // What is shown (color's alpha travels with it), or everything while an EXR waits.
    if (everyAov_) model_.setRenderedAovs({});
    else model_.setRenderedAovs(settings_.aov == "color" ? std::vector<std::string>{"color"}
                                                         : std::vector<std::string>{"color", settings_.aov});
    try {
        model_.advance(hud_.frameMs / 1000.0);
    } catch (const Error& e) {
        hud_.message = std::string("error: scene time: ") + e.what();
    }
    const int submitted = model_.update();
    if (measure_) {
        measure_->frame();
        if (submitted > 0) measure_->edited(submitted, Clock::now());
    }
    refreshPicture();
    refreshReference();
    glViewport(0, 0, width, height);
    picture_.draw();
    if (wipe_.on && reference_) reference_->draw(wipeColumn_, width, height);
    imgui_.render();
    if (screenshot_) {
        saveScreenshot(*screenshot_, width, height);
        std::cout << "opal-view: wrote " << screenshot_->string() << std::endl;
        screenshot_.reset();
    }
    lastWait_ = window_.swapBuffers(frameInterval(), [this] { return pictureWaiting(); });
}

// 60 frames a second at most (a display without vertical sync would draw as fast as the CPU
// allows). With software OpenGL the interface's drawing takes the cores the renderer needs,
// so while a sync runs that takes longer than a frame (a dragged light relights for tens of
// milliseconds; a material edit for a few) it draws 30.
std::chrono::microseconds Viewer::frameInterval() const {
    const SessionStatus status = model_.isOpen() ? model_.session().status() : SessionStatus{};
    const bool relighting = status.busy && status.lastSyncMs > 1000.0 / FramesPerSecond;
    return std::chrono::microseconds(1'000'000 / (softwareOpenGl_ && relighting ? SlowFramesPerSecond : FramesPerSecond));
}

// What the interface should not wait out its frame interval for: a converted picture to
// show, or a picture due for converting (refreshPicture's own rule, so that the frame this
// wakes asks for it and the wait ends once). Without it a picture waited up to two frames
// for the interface.
bool Viewer::pictureWaiting() const {
    if (!model_.isOpen()) return false;
    if (converter_.ready()) return true;
    return !converter_.busy() && duePicture().has_value();
}

void Viewer::carryOut(const FileRequest& request) {
    try {
        switch (request.action) {
        case FileAction::Open: open(request.file); break;
        case FileAction::SaveScene: model_.saveScene(request.file); break;
        case FileAction::SavePicture: savePng(request.file); break;
        }
        menu_.status = (request.action == FileAction::Open ? "opened " : "wrote ") + request.file.string();
    } catch (const std::exception& e) {
        menu_.status = std::string("error: ") + e.what();
        std::cerr << "opal-view: error: " << e.what() << '\n';
    }
}

void Viewer::openDropped() {
    const std::vector<std::filesystem::path> dropped = window_.takeDroppedFiles();
    if (dropped.empty()) return;
    if (dropped.size() > 1) std::cerr << "opal-view: warning: " << dropped.size() << " files dropped: opening the first\n";
    try {
        open(dropped.front());
        hud_.message.clear();
    } catch (const std::exception& e) {
        hud_.message = "error: " + dropped.front().string() + ": " + e.what();
        std::cerr << "opal-view: " << hud_.message << '\n';
    }
}

void Viewer::updateTitle() {
    const std::string title = model_.title();
    if (title == title_) return;
    title_ = title;
    window_.setTitle(title);
}

void Viewer::drawInterface() {
    // A slider held or a light dragged is one undo step, however many frames it lasts.
    model_.setMergingEdits(ImGui::IsAnyItemActive() || ImGui::IsMouseDown(ImGuiMouseButton_Left));
    if (const std::optional<FileRequest> request = menu_.draw(model_, panels_, recent_.files())) carryOut(*request);
    handleViewportInput(model_, panels_);
    ImGui::SetNextWindowPos(ImVec2(10.0f, 30.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(PanelWidth, 0.0f), ImGuiCond_FirstUseEver);
    // Above the heads-up line, however small the window.
    const float tallest = std::max(ImGui::GetIO().DisplaySize.y - HudHeight, 100.0f);
    ImGui::SetNextWindowSizeConstraints(ImVec2(PanelWidth, 0.0f), ImVec2(PanelWidth, tallest));
    ImGui::Begin("Look");
    drawMaterialPanel(model_, materialPanel_);
    drawLightPanel(model_, lightPanel_);
    drawEnvironmentPanel(model_, environment_);
    drawCameraPanel(model_);
    drawColorPanel(display_, settings_, model_.session().aovs());
    drawWipeToggle();
    ImGui::End();
    drawKeyboardHelp(panels_.help);
    drawStatsPanel(*renderer_.delegate, panels_.stats);
    drawRenderSettingsPanel(model_, *renderer_.delegate, panels_.settings, settingsProblem_);
    chosenDelegate_ = drawDelegatePicker(delegateChoices(registry_, renderer_.plugin.info().typeName),
                                         registry_.problems(), panels_.delegates);
    if (panels_.probe) drawProbeTooltip(model_, shownPicture(), shownAov_);
    if (panels_.gizmos) drawLightGizmos(model_);
    drawHud(model_, hud_);
    if (wipe_.on) wipeColumn_ = drawWipeLine(wipe_);
}

// The A/B wipe's switch (also W); a renderer without a reference says so in the HUD.
void Viewer::drawWipeToggle() {
    bool on = wipe_.on;
    const bool key = !ImGui::GetIO().WantCaptureKeyboard && !ImGui::GetIO().KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_W, false);
    if (!ImGui::Checkbox("A/B wipe: engine | reference (W)", &on) && !key) return;
    try {
        setWipe(key ? !wipe_.on : on, std::nullopt);
    } catch (const Error& e) {
        hud_.message = std::string("error: ") + e.what();
    }
}

void Viewer::collectMessages() {
    if (!model_.isOpen()) return;
    std::vector<std::string> messages = model_.session().takeMessages();
    if (RenderSession* reference = model_.referenceSession())
        for (const std::string& message : reference->takeMessages()) {
            const std::size_t kind = message.find(": ") + 2;  // after "error: " or "warning: "
            messages.push_back(message.substr(0, kind) + "reference: " + message.substr(kind));
        }
    for (const std::string& message : messages) {
        std::cerr << "opal-view: " << message << '\n';
        hud_.message = message;
        if (message.starts_with("error: ") && renderError_.empty()) renderError_ = message.substr(7);
    }
}

namespace {

bool sameFrame(const PictureTag& a, const PictureTag& b) {
    return a.passes == b.passes && a.syncs == b.syncs && a.settings == b.settings;
}

}  // namespace

PictureTag Viewer::currentTag() const { return pictureTagOf(model_.session(), settings_.version); }

void Viewer::refreshReference() {
    if (!wipe_.on || !reference_ || !model_.referenceSession()) return;
    const std::string error = reference_->refresh(*model_.referenceSession(), display_, settings_);
    if (!error.empty()) hud_.message = "error: reference: " + error;
}

// The session's picture, when one is due for showing: the first pass of a new edit, a
// settled frame not yet shown settled, or a refinement RefineInterval after the last.
std::optional<PictureTag> Viewer::duePicture() const {
    // Read before the buffer is: a settled session writes nothing more into it, and a
    // sync's restart has reset the pass count by the time its status is published.
    const bool settled = model_.settled();
    const int applied = model_.session().status().applied;
    PictureTag tag = currentTag();
    tag.applied = applied;
    tag.settled = settled;
    const bool newEdit = tag.passes >= 1 && tag.applied > requested_.applied;
    const bool due = settled ? !(sameFrame(tag, requested_) && requested_.settled)
                             : newEdit || (!sameFrame(tag, requested_) && Clock::now() - lastPicture_ >= RefineInterval);
    if (!due) return std::nullopt;
    return tag;
}

void Viewer::refreshPicture() {
    if (!model_.isOpen()) return;
    showConverted();
    const std::optional<PictureTag> due = duePicture();
    if (!due) return;
    const PictureTag& tag = *due;
    const bool settled = tag.settled;
    const Clock::time_point now = Clock::now();
    if (gpuDisplay()) return uploadSceneLinear(tag);
    PictureRequest request{&model_.session().buffer(settings_.aov), settings_.aov, display_.display(), display_.view(),
                           settings_.grade, tag, settled ? 1 : tag.passes <= 1 ? std::max(2, draftBlock_) : 2};
    if (!converter_.request(std::move(request))) return;
    requested_ = tag;
    lastPicture_ = now;
}

void Viewer::shown(const PictureTag& tag) {
    shown_ = tag;
    // A pass of the frame the newest sync started: the picture shows that edit.
    if (shown_.passes >= 1 && shown_.applied > shownApplied_) {
        shownApplied_ = shown_.applied;
        if (measure_) measure_->shown(shownApplied_, Clock::now());
    }
}

void Viewer::showConverted() {
    std::optional<ConvertedPicture> done = converter_.take();
    // A conversion of an AOV shown before the GPU's transform took over: older than what it shows.
    if (!done || gpuDisplay()) return;
    if (!done->error.empty()) hud_.message = "error: " + done->error;
    else if (!done->image.empty()) picture_.upload(done->image);
    if (done->error.empty()) {
        shownImage_ = std::move(done->image);
        shownImageStale_ = false;
        shownAov_ = settings_.aov;
    }
    shown(done->tag);
}

bool Viewer::gpuDisplay() const { return gpuDisplayError_.empty() && isRadiometric(settings_.aov); }

void Viewer::uploadSceneLinear(const PictureTag& tag) {
    try {
        picture_.setDisplay(display_.config(), display_.display(), display_.view(), settings_.grade);
        const Image linear = mappedImage(model_.session().buffer(settings_.aov));  // the copy frees the buffer at once
        if (!linear.empty()) picture_.uploadSceneLinear(linear.pixels().data(), linear.width(), linear.height(), linear.channels());
    } catch (const Error& e) {
        gpuDisplayError_ = e.what();
        hud_.message = "warning: the display transform runs on the CPU: " + gpuDisplayError_;
        std::cerr << "opal-view: " << hud_.message << '\n';
        return;  // the converter shows the next picture
    }
    requested_ = tag;
    lastPicture_ = Clock::now();
    shownAov_ = settings_.aov;
    shownImageStale_ = true;
    shown(tag);
}

const Image& Viewer::shownPicture() {
    if (shownImageStale_) {
        shownImage_ = picture_.displayed();
        shownImageStale_ = false;
    }
    return shownImage_;
}

bool Viewer::pictureSettled() {
    const bool referenceShown =
        !wipe_.on || (reference_ && model_.referenceSession() && reference_->settled(*model_.referenceSession(), settings_));
    return model_.settled() && shown_.settled && sameFrame(currentTag(), shown_) && referenceShown &&
           framesSincePanels_ >= PanelLayoutFrames;
}

void Viewer::setWipe(bool on, std::optional<double> split) {
    if (split && !(*split >= 0.0 && *split <= 1.0))
        throw Error("wipe " + std::to_string(*split) + ": the line's place is a fraction of the width, 0 to 1");
    if (split) wipe_.split = *split;
    if (on == wipe_.on) return;
    if (on) {
        if (!referenceDelegate_) referenceDelegate_.emplace(renderer_.plugin.createRenderDelegate());
        if (!reference_) reference_.emplace(display_.config());
        reference_->reset(display_.config());  // a new session: its pictures start again
        model_.showReference(referenceDelegate_->get());
    } else {
        reference_->drain();
        model_.showReference(nullptr);
    }
    wipe_.on = on;
    framesSincePanels_ = 0;
}

void Viewer::beginMeasure() { measure_.emplace(Clock::now()); }

std::string Viewer::endMeasure() {
    const std::string summary = measure_ ? measure_->summary(Clock::now()) : "";
    measure_.reset();
    return summary;
}

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
    settings_.grade.exposure = stops;
    ++settings_.version;
}

void Viewer::setGamma(double gamma) {
    if (!(gamma > 0.0) || !std::isfinite(gamma)) throw Error("gamma " + std::to_string(gamma) + " is not a positive number");
    settings_.grade.gamma = gamma;
    ++settings_.version;
}

void Viewer::setAov(const std::string& aov) {
    if (!hd::findAov(aov)) throw Error("unknown AOV '" + aov + "' (AOVs: " + hd::aovNameList() + ")");
    if (model_.isOpen() && !model_.session().renders(aov))
        throw Error("the renderer " + renderer_.plugin.info().displayName + " renders no AOV '" + aov + "' (it renders " +
                    model_.session().aovList() + ")");
    settings_.aov = aov;
    ++settings_.version;
}

void Viewer::showPanel(const std::string& panel, bool open) {
    bool* shown = panel == "help"       ? &panels_.help
                  : panel == "stats"    ? &panels_.stats
                  : panel == "settings" ? &panels_.settings
                  : panel == "probe"    ? &panels_.probe
                  : panel == "gizmos"   ? &panels_.gizmos
                  : panel == "delegates" ? &panels_.delegates
                                        : nullptr;
    if (!shown) throw Error("unknown panel '" + panel + "' (panels: help, stats, settings, probe, gizmos, delegates)");
    *shown = open;
    framesSincePanels_ = 0;
}

void Viewer::requestScreenshot(const std::filesystem::path& file) {
    if (file.extension() != ".png") throw Error("screenshot " + file.string() + ": the file must end in .png");
    const std::filesystem::path folder = std::filesystem::absolute(file).parent_path();
    if (!std::filesystem::is_directory(folder))
        throw Error("screenshot " + file.string() + ": the folder " + folder.string() + " does not exist");
    screenshot_ = file;
}

void Viewer::renderEveryAov() {
    everyAov_ = true;
    model_.setRenderedAovs({});  // now, so that the model is not settled until they are rendered
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
    everyAov_ = false;
}

void Viewer::savePng(const std::filesystem::path& file) {
    if (file.extension() != ".png") throw Error("save png " + file.string() + ": the file must end in .png");
    const Image linear = mappedImage(model_.session().buffer(settings_.aov));
    if (linear.empty()) throw Error("save png " + file.string() + ": nothing is rendered yet");
    Image picture;
    // Isolated: this thread must not pick up the renderer's tiles meanwhile.
    tbb::this_task_arena::isolate([&] { picture = display_.toFile(linear, settings_.aov, settings_.grade); });
    writePreview(file, picture);
    std::cout << "opal-view: wrote " << file.string() << std::endl;
}

std::string Viewer::probe(int x, int y) {
    everyAov_ = false;
    const PixelProbe probe{x, y, probeAovs(model_.session().buffers(), x, y), shownAov_,
                           shownValue(shownPicture(), x, y, model_.width(), model_.height())};
    return probeReport(probe);
}

}  // namespace opal::view
