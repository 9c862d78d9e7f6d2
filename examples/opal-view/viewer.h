// The viewer: a window showing the newest picture of the open scene with the panels over
// it, frame after frame, until the window closes or a script quits. The interface never
// waits for the renderer: edits go to the render session's worker, and each frame shows
// whatever the AOV buffer holds (converted again only when it changed).
#pragma once

#include "examples/opal-view/core/display_picture.h"
#include "examples/opal-view/core/renderer_loader.h"
#include "examples/opal-view/core/script_runner.h"
#include "examples/opal-view/core/viewer_model.h"
#include "examples/opal-view/display_settings.h"
#include "examples/opal-view/hud.h"
#include "examples/opal-view/imgui_layer.h"
#include "examples/opal-view/picture_texture.h"
#include "examples/opal-view/view_options.h"
#include "examples/opal-view/window.h"

#include <chrono>
#include <optional>

namespace opal::view {

class Viewer final : public ScriptHost {
public:
    // Loads the renderer, opens the window and the scene; throws opal::Error.
    Viewer(const ViewOptions& options, std::vector<ScriptAction> script);

    // Until the window closes or the script quits; throws opal::Error when a script
    // action fails ("FILE:LINE: ...").
    void run();

    ViewerModel& model() override { return model_; }
    void open(const std::filesystem::path& file) override;
    void setDisplayView(const std::string& display, const std::string& view) override;
    void setExposure(double stops) override;
    void setAov(const std::string& aov) override;
    bool pictureSettled() override;
    std::string takeRenderError() override;
    void requestScreenshot(const std::filesystem::path& file) override;
    void saveExr(const std::filesystem::path& file) override;
    void quit() override { quit_ = true; }

private:
    // What the shown picture was made from; a new one is made when this changes.
    struct PictureKey {
        int passes = -1, syncs = -1, settings = -1;
        friend bool operator==(const PictureKey&, const PictureKey&) = default;
    };
    void frame();
    void drawInterface();
    void collectMessages();
    void refreshPicture();
    PictureKey pictureKey() const;

    LoadedRenderer renderer_;  // first: outlives the session that renders with it
    Window window_;
    ImGuiLayer imgui_;
    PictureTexture picture_;
    DisplayPicture display_;
    DisplaySettings settings_;
    std::optional<ScriptRunner> script_;
    std::optional<std::filesystem::path> screenshot_;
    HudFigures hud_;
    std::string renderError_;
    PictureKey shown_;
    bool shownSettled_ = false, quit_ = false;
    std::chrono::steady_clock::time_point lastPicture_, lastFrame_;
    ViewerModel model_;  // last: its render session goes before everything above
};

}  // namespace opal::view
