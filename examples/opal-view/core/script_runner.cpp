#include "examples/opal-view/core/script_runner.h"

#include "examples/opal-view/core/color_temperature.h"
#include "examples/opal-view/core/edited_scene.h"
#include "examples/opal-view/core/environment_edit.h"
#include "examples/opal-view/core/light_drag.h"
#include "examples/opal-view/core/light_flicker_edit.h"
#include "examples/opal-view/core/light_shape.h"
#include "schema/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace opal::view {
namespace {

constexpr double DefaultWaitSeconds = 300.0;

void runMaterial(const ScriptAction& action, ViewerModel& model) {
    if (action.kind == ActionKind::MaterialReset) return model.resetMaterial();
    if (action.kind == ActionKind::MaterialPreset) return model.applyPreset(action.words.at(0));
    model.setMaterialParameter(action.words.at(0), action.numbers);
}

void say(const std::string& line) {
    std::printf("opal-view: %s\n", line.c_str());
    std::fflush(stdout);
}

// Adding, removing, renaming, enabling: what changes which lights there are.
void runLightSet(const ScriptAction& action, ViewerModel& model) {
    switch (action.kind) {
    case ActionKind::LightAdd: {
        const bool field = action.words[0] == "shadowfield";
        std::optional<hd::SdfPath> path;
        if (action.words.size() > (field ? 2u : 1u)) path = action.words.back();
        say("added light " + (field ? model.addShadowFieldLight(action.words[1], path)
                                    : model.addLight(newLightKind(action.words[0]).value(), path)));
        return;
    }
    case ActionKind::LightRemove: return model.removeLight(action.words.at(0));
    case ActionKind::LightRename: say("renamed light to " + model.renameLight(action.words.at(0), action.words.at(1))); return;
    case ActionKind::LightEnable: return model.setLightEnabled(action.words.at(1), action.words[0] == "enable");
    default: return;
    }
}

void runHistory(const ScriptAction& action, ViewerModel& model) {
    const bool undo = action.kind == ActionKind::Undo;
    if (!(undo ? model.undo() : model.redo())) throw Error(undo ? "nothing to undo" : "nothing to redo");
}

void runLight(const ScriptAction& action, ViewerModel& model) {
    const hd::SdfPath& path = action.words.at(0);
    if (action.kind == ActionKind::LightMove)
        return model.moveLight(path, {action.numbers[0], action.numbers[1], action.numbers[2]});
    hd::LightDesc light = model.light(path);
    if (action.kind == ActionKind::LightTurn) {
        if (light.kind != hd::LightKind::Distant)
            throw Error("<" + path + "> is not a distant light (light move places the others)");
        return model.setLight(path, turnedLight(model.viewedCamera(), light, action.numbers[0], action.numbers[1]));
    }
    const std::string& parameter = action.words.at(1);
    if (parameter == "intensity") light.intensity = action.numbers[0];
    if (parameter == "exposure") light.exposure = action.numbers[0];
    if (parameter == "color") light.color = Rgb{action.numbers[0], action.numbers[1], action.numbers[2]};
    if (parameter == "temperature") setColorTemperature(light, action.numbers.empty() ? 0.0 : action.numbers[0]);
    if (parameter == "flicker") setFlicker(light, action.numbers[0], action.numbers[1], action.numbers[2]);
    for (const std::string_view shape : lightShapeParameters())
        if (parameter == shape) setShapeParameter(light, parameter, action.numbers[0]);
    model.setLight(path, light);
}

void runEnvironment(const ScriptAction& action, ViewerModel& model) {
    const std::optional<hd::SdfPath> dome = environmentLight(model.scene());
    if (!dome) throw Error("the scene has no dome light (add one: light add dome)");
    hd::LightDesc light = model.light(*dome);
    const std::string& what = action.words.at(0);
    if (what == "rotate") rotateEnvironment(light, action.numbers.at(0));
    if (what == "texture") setEnvironmentTexture(light, action.words.at(1));
    if (what == "background") light.visibleToCamera = action.words.at(1) == "on";
    model.setLight(*dome, light);
}

void runCamera(const ScriptAction& action, ViewerModel& model) {
    switch (action.kind) {
    case ActionKind::CameraFrame: return action.words.empty() ? model.frameAll() : model.frameSelection();
    case ActionKind::CameraReset: return model.resetCamera();
    case ActionKind::CameraUse:
        if (action.words[0] == "free") model.useFreeCamera();
        else model.useCamera(action.words[0]);
        return;
    case ActionKind::CameraFocal: return setFocalLength(model.useFreeCamera(), action.numbers[0]);
    case ActionKind::CameraFov: return setHorizontalFieldOfView(model.useFreeCamera(), action.numbers[0], model.aspect());
    case ActionKind::CameraClip:
        if (action.numbers.empty()) return setAutomaticClipping(model.useFreeCamera());
        return setClipping(model.useFreeCamera(), action.numbers[0], action.numbers[1]);
    default: {
        OrbitCamera& camera = model.useFreeCamera();
        camera.yaw += action.numbers[0];
        camera.pitch = std::clamp(camera.pitch + action.numbers[1], -89.0, 89.0);
    }
    }
}

// A mesh or a light of the scene.
void runSelect(const std::string& path, ViewerModel& model) {
    if (model.scene().meshes.count(path)) return model.selectMesh(path);
    if (model.scene().lights.count(path)) {
        model.selectedLight = path;
        return;
    }
    throw Error("no mesh or light <" + path + "> in the scene");
}

// The sigma_a green slider swept log-uniformly over the asset's range, 2 s a sweep.
void dragMaterial(ViewerModel& model, double seconds) {
    const EditableRange& range = model.selectedAsset().range;
    const double phase = 0.5 + 0.5 * std::sin(std::numbers::pi * seconds);
    hd::MaterialDesc material = model.selectedMaterial();
    material.subsurface.sigmaA[1] = range.sigmaAMin * std::pow(range.sigmaAMax / range.sigmaAMin, phase);
    model.setSelectedMaterial(material);
}

// The light swept around the object's centre on its sphere: a quarter turn a second about
// +Y, and tipped by up to 30 degrees about +X (so a light straight above moves too). A
// distant light turns so instead, its position kept.
void dragLight(ViewerModel& model, const hd::SdfPath& path, const hd::LightDesc& home, double seconds) {
    const Imath::V3d center = model.bounds().center;
    Imath::M44d turn;
    turn.rotate(Imath::V3d(std::numbers::pi / 6.0 * std::sin(std::numbers::pi * seconds), 0.5 * std::numbers::pi * seconds, 0.0));
    if (home.kind == hd::LightKind::Distant) {
        hd::LightDesc turned = home;
        turned.transform = home.transform * turn;
        return model.setLight(path, movedLight(turned, lightPosition(home)));
    }
    Imath::V3d offset;
    turn.multDirMatrix(lightPosition(home) - center, offset);
    model.moveLight(path, center + offset);
}

std::string actionName(const ScriptAction& action) {
    switch (action.kind) {
    case ActionKind::Wait: return "wait";
    case ActionKind::Drag: return "drag";
    case ActionKind::SavePng: return "save png";
    case ActionKind::Probe: return "probe";
    default: return "save exr";
    }
}

}  // namespace

template <class F>
bool ScriptRunner::withEveryAov(const ScriptAction& action, ScriptHost& host, F&& then) {
    if (!waiting_) host.renderEveryAov();
    if (!waitForPicture(action, host, DefaultWaitSeconds)) return false;
    then();
    return true;
}

bool ScriptRunner::drag(const ScriptAction& action, ScriptHost& host) {
    using Clock = std::chrono::steady_clock;
    const bool light = action.words[0] == "light";
    if (!dragging_) {
        dragging_ = true;
        dragStart_ = Clock::now();
        if (light) dragHome_ = host.model().light(action.words[1]);
        host.beginMeasure();
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - dragStart_).count();
    if (seconds < action.numbers.back()) {
        if (light) dragLight(host.model(), action.words[1], dragHome_, seconds);
        else dragMaterial(host.model(), seconds);
        lastEdit_ = Clock::now();
        return false;
    }
    if (!waitForPicture(action, host, DefaultWaitSeconds)) return false;
    const double settle = std::chrono::duration<double, std::milli>(Clock::now() - lastEdit_).count();
    std::printf("opal-view: %s drag %s: %s; converged %.0f ms after the last edit\n", action.where.c_str(),
                action.words[0].c_str(), host.endMeasure().c_str(), settle);
    std::fflush(stdout);
    dragging_ = false;
    return true;
}

bool ScriptRunner::step(ScriptHost& host) {
    while (next_ < actions_.size()) {
        const ScriptAction& action = actions_[next_];
        try {
            const std::string error = host.takeRenderError();
            if (!error.empty()) throw Error("the renderer failed: " + error);
            if (!run(action, host)) return false;
        } catch (const Error& e) {
            throw Error(action.where + ": " + e.what());
        }
        ++next_;
        // A screenshot is taken at the end of this frame: nothing may change before it.
        if (action.kind == ActionKind::Screenshot) return next_ == actions_.size();
    }
    return true;
}

bool ScriptRunner::waitForPicture(const ScriptAction& action, ScriptHost& host, double seconds) {
    if (!waiting_) waitStart_ = std::chrono::steady_clock::now();
    waiting_ = true;
    if (host.pictureSettled()) {
        waiting_ = false;
        return true;
    }
    const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - waitStart_).count();
    if (waited > seconds)
        throw Error(actionName(action) + ": the picture did not converge within " + std::to_string(int(seconds)) + " s");
    return false;
}

bool ScriptRunner::run(const ScriptAction& action, ScriptHost& host) {
    ViewerModel& model = host.model();
    switch (action.kind) {
    case ActionKind::Load: host.open(action.words[0]); return true;
    case ActionKind::MaterialSet:
    case ActionKind::MaterialReset:
    case ActionKind::MaterialPreset: runMaterial(action, model); return true;
    case ActionKind::LightAdd:
    case ActionKind::LightRemove:
    case ActionKind::LightRename:
    case ActionKind::LightEnable: runLightSet(action, model); return true;
    case ActionKind::Environment: runEnvironment(action, model); return true;
    case ActionKind::Undo:
    case ActionKind::Redo: runHistory(action, model); return true;
    case ActionKind::Setting: model.setRenderSettingText(action.words[0], action.words[1]); return true;
    case ActionKind::LightMove:
    case ActionKind::LightTurn:
    case ActionKind::LightSet: runLight(action, model); return true;
    case ActionKind::View: host.setDisplayView(action.words[0], action.words[1]); return true;
    case ActionKind::Exposure: host.setExposure(action.numbers[0]); return true;
    case ActionKind::Gamma: host.setGamma(action.numbers[0]); return true;
    case ActionKind::Aov: host.setAov(action.words[0]); return true;
    case ActionKind::Delegate:
        host.useDelegate(action.words[0]);
        say("delegate " + action.words[0]);
        return true;
    case ActionKind::Delegates:
        std::printf("%s", host.delegateListing().c_str());
        std::fflush(stdout);
        return true;
    case ActionKind::Wipe:
        if (action.numbers.empty()) host.setWipe(action.words[0] == "on", std::nullopt);
        else host.setWipe(true, action.numbers[0]);
        return true;
    case ActionKind::Panel: host.showPanel(action.words[0], action.words[1] == "on"); return true;
    case ActionKind::Gizmos: host.showPanel("gizmos", action.words[0] == "on"); return true;
    case ActionKind::CameraFrame:
    case ActionKind::CameraReset:
    case ActionKind::CameraOrbit:
    case ActionKind::CameraFocal:
    case ActionKind::CameraUse:
    case ActionKind::CameraFov:
    case ActionKind::CameraClip: runCamera(action, model); return true;
    case ActionKind::Select: runSelect(action.words[0], model); return true;
    case ActionKind::Time:
        model.playing = false;
        model.setTime(action.numbers[0]);
        return true;
    case ActionKind::Play: model.playing = action.words[0] == "play"; return true;
    case ActionKind::Wait:
        return waitForPicture(action, host, action.numbers.empty() ? DefaultWaitSeconds : action.numbers[0]);
    case ActionKind::Drag: return drag(action, host);
    case ActionKind::Screenshot: host.requestScreenshot(action.words[0]); return true;
    case ActionKind::SaveExr: return withEveryAov(action, host, [&] { host.saveExr(action.words[0]); });
    case ActionKind::SavePng:
        if (!waitForPicture(action, host, DefaultWaitSeconds)) return false;
        host.savePng(action.words[0]);
        return true;
    case ActionKind::SaveUsda:
        model.saveScene(action.words[0]);
        say("wrote " + action.words[0]);
        return true;
    case ActionKind::Probe:
        if (action.numbers[0] != std::floor(action.numbers[0]) || action.numbers[1] != std::floor(action.numbers[1]))
            throw Error("probe: X and Y are whole pixels");
        return withEveryAov(action, host, [&] {
            std::printf("%s", host.probe(int(action.numbers[0]), int(action.numbers[1])).c_str());
            std::fflush(stdout);
        });
    case ActionKind::Quit: host.quit(); return true;
    }
    return true;
}

}  // namespace opal::view
