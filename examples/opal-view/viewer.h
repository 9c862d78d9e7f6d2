// The viewer: a window showing the newest picture of the open scene with the panels over
// it, frame after frame, until the window closes or a script quits. The interface never
// waits for the renderer: edits go to the render session's worker, and each frame shows
// whatever the AOV buffer holds (converted again only when it changed).
#pragma once

#include "examples/opal-view/core/display_picture.h"
#include "examples/opal-view/core/edit_latency.h"
#include "examples/opal-view/core/picture_converter.h"
#include "examples/opal-view/core/recent_files.h"
#include "examples/opal-view/core/renderer_loader.h"
#include "examples/opal-view/core/script_runner.h"
#include "examples/opal-view/core/viewer_model.h"
#include "examples/opal-view/display_settings.h"
#include "examples/opal-view/environment_panel.h"
#include "examples/opal-view/hud.h"
#include "examples/opal-view/imgui_layer.h"
#include "examples/opal-view/light_panel.h"
#include "examples/opal-view/material_panel.h"
#include "examples/opal-view/menu_bar.h"
#include "examples/opal-view/panel_visibility.h"
#include "examples/opal-view/gl/picture_texture.h"
#include "examples/opal-view/reference_picture.h"
#include "examples/opal-view/view_options.h"
#include "examples/opal-view/window.h"
#include "examples/opal-view/wipe_overlay.h"

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
    void setGamma(double gamma) override;
    void setAov(const std::string& aov) override;
    // Tears the render session down and builds it again on the new plugin's delegate (the
    // same scene, camera, edits and display; the settings panel follows its descriptors);
    // if the new delegate refuses the scene, the old one renders it again and this throws.
    void useDelegate(const std::string& typeName) override;
    std::string delegateListing() override;
    void setWipe(bool on, std::optional<double> split) override;
    void showPanel(const std::string& panel, bool open) override;
    bool pictureSettled() override;
    std::string takeRenderError() override;
    void requestScreenshot(const std::filesystem::path& file) override;
    void renderEveryAov() override;
    void saveExr(const std::filesystem::path& file) override;
    void savePng(const std::filesystem::path& file) override;
    std::string probe(int x, int y) override;
    void quit() override { quit_ = true; }
    void beginMeasure() override;
    std::string endMeasure() override;

private:
    void frame();
    std::chrono::microseconds frameInterval() const;  // the interface's pace (frame())
    bool pictureWaiting() const;                      // ends a frame's wait early
    static constexpr int FramesPerSecond = 60, SlowFramesPerSecond = 30;
    void drawInterface();
    void collectMessages();
    void refreshPicture();
    std::optional<PictureTag> duePicture() const;
    // The picture's new state is on screen: what a drag measures.
    void shown(const PictureTag& tag);
    void showConverted();
    // The radiometric AOV's buffer, scene-linear, to the GPU's display transform.
    void uploadSceneLinear(const PictureTag& tag);
    // Whether the shown AOV goes through the GPU's display transform (else the converter's CPU one).
    bool gpuDisplay() const;
    // What the probe reports as shown: read back from the GPU when it changed since.
    const Image& shownPicture();
    // The wipe's reference picture: converted and shown while the wipe is on.
    void refreshReference();
    void drawWipeToggle();
    void updateTitle();
    void carryOut(const FileRequest& request);
    // Opens what was dropped on the window (the first file), reporting failures in the HUD.
    void openDropped();
    // The frame the buffers hold now (passes, syncs, display settings).
    PictureTag currentTag() const;
    // The display follows the delegate's OCIO config (a scene's opal:ocioConfig); returns it.
    ColorConfig adoptDelegateConfig();
    // What the picker chose this frame, carried out once the interface is drawn.
    void carryOutDelegateChoice();

    PluginRegistry registry_;  // what the delegate picker lists
    LoadedRenderer renderer_;  // outlives the session that renders with it
    std::optional<RenderDelegateHandle> referenceDelegate_;  // the wipe's, made when first needed
    Window window_;
    ImGuiLayer imgui_;
    PictureTexture picture_;
    DisplayPicture display_;  // the display and view chosen (the converter has its own)
    DisplaySettings settings_;
    std::optional<ScriptRunner> script_;
    std::optional<std::filesystem::path> screenshot_;
    HudFigures hud_;
    Image shownImage_;      // the display-referred picture on screen (for the probe)
    bool shownImageStale_ = false;  // the GPU drew a newer one
    std::string gpuDisplayError_;   // why the GPU's display transform is off (the CPU's shows then)
    int draftBlock_ = 1;            // the delegate's draft pictures: one ray per N x N pixels
    bool softwareOpenGl_ = false;   // the interface's drawing runs on the renderer's cores
    std::string shownAov_;  // what it shows
    std::string title_;
    MenuBar menu_;
    RecentFiles recent_;
    PanelVisibility panels_;
    LightPanelState lightPanel_;
    MaterialPanelState materialPanel_;
    std::string settingsProblem_;
    std::optional<std::string> chosenDelegate_;  // by the picker, this frame
    EnvironmentPanelState environment_;
    int framesSincePanels_ = 0;  // interface frames drawn since a script opened or closed a panel
    std::string renderError_;
    PictureTag requested_, shown_;
    int shownApplied_ = 0;                 // the newest submission a shown picture holds
    std::optional<EditLatency> measure_;   // while a script's drag runs
    bool quit_ = false, everyAov_ = false;
    std::chrono::steady_clock::time_point lastPicture_, lastFrame_;
    std::chrono::steady_clock::duration lastWait_{};  // the last frame's pacing wait (Window::swapBuffers)
    ViewerModel model_;  // its render session goes before everything above
    PictureConverter converter_;  // stops reading the session's buffers first
    WipeState wipe_;
    int wipeColumn_ = 0;  // the line's framebuffer column this frame
    std::optional<ReferencePicture> reference_;  // last: made on the first wipe (needs the GL context)
};

}  // namespace opal::view
