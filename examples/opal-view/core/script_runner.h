// Runs a parsed opal-view script against the viewer, one interface frame at a time: the
// actions that need the renderer (wait, save exr) hold the script until the picture
// converged, without holding the interface. Every failure is an opal::Error prefixed
// with the action's FILE:LINE.
#pragma once

#include "examples/opal-view/core/script.h"
#include "examples/opal-view/core/viewer_model.h"

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace opal::view {

// What a script reaches beyond the model: the window and what it shows.
class ScriptHost {
public:
    virtual ~ScriptHost() = default;
    virtual ViewerModel& model() = 0;
    virtual void open(const std::filesystem::path& file) = 0;  // loads and resets the display
    virtual void setDisplayView(const std::string& display, const std::string& view) = 0;
    virtual void setExposure(double stops) = 0;
    virtual void setGamma(double gamma) = 0;  // throws opal::Error unless positive
    virtual void setAov(const std::string& aov) = 0;
    // Renders with the renderer plugin of that type from now on (the same scene, camera and
    // edits); throws opal::Error listing the available ones for an unknown type.
    virtual void useDelegate(const std::string& typeName) = 0;
    // The delegate picker's list (plugin/plugin_listing.h's, the current one marked).
    virtual std::string delegateListing() = 0;
    // The A/B wipe on or off; a split (a fraction of the width, 0 to 1; throws opal::Error
    // otherwise) moves its line and turns it on.
    virtual void setWipe(bool on, std::optional<double> split) = 0;
    // Opens or closes an optional panel: help, stats, settings, probe, or the light gizmos.
    virtual void showPanel(const std::string& panel, bool open) = 0;
    // The renderer converged on the latest edit and the window shows that picture.
    virtual bool pictureSettled() = 0;
    // The first error the renderer reported since the last call, or "".
    virtual std::string takeRenderError() = 0;
    // The window's pixels at the end of this frame, interface included.
    virtual void requestScreenshot(const std::filesystem::path& file) = 0;
    // The renderer writes every AOV until the next saveExr (which needs them all).
    virtual void renderEveryAov() = 0;
    virtual void saveExr(const std::filesystem::path& file) = 0;
    // The AOV shown, display-referred, at the renderer's resolution (DisplayPicture::toFile).
    virtual void savePng(const std::filesystem::path& file) = 0;
    // Every AOV's values at pixel (x, y) from the top left and the shown display value,
    // one line each (pixel_probe.h); needs every AOV rendered (renderEveryAov).
    virtual std::string probe(int x, int y) = 0;
    // Starts measuring what the interface shows (edit_latency.h); end returns the summary.
    virtual void beginMeasure() = 0;
    virtual std::string endMeasure() = 0;
    virtual void quit() = 0;
};

class ScriptRunner {
public:
    explicit ScriptRunner(std::vector<ScriptAction> actions) : actions_(std::move(actions)) {}

    // Runs actions until one must wait for a later frame or the script ends; true once
    // every action ran. Throws opal::Error "FILE:LINE: ...".
    bool step(ScriptHost& host);

private:
    // Whether the action is done (false: call again next frame).
    bool run(const ScriptAction& action, ScriptHost& host);
    bool waitForPicture(const ScriptAction& action, ScriptHost& host, double seconds);
    // Waits for every AOV to converge, then does `then`.
    template <class F>
    bool withEveryAov(const ScriptAction& action, ScriptHost& host, F&& then);
    bool drag(const ScriptAction& action, ScriptHost& host);

    std::vector<ScriptAction> actions_;
    std::size_t next_ = 0;
    bool waiting_ = false;
    std::chrono::steady_clock::time_point waitStart_;
    bool dragging_ = false;
    std::chrono::steady_clock::time_point dragStart_, lastEdit_;
    hd::LightDesc dragHome_;  // the light when the drag began
};

}  // namespace opal::view
