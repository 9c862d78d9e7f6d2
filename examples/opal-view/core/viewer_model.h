// Everything the viewer edits and renders, without a window: the open document, the
// interface's copy of its scene, the free camera, the selection, and the render session
// the edits go to. The interface and the script runner both drive it; update() once per
// interface frame hands what changed to the session (returning at once).
#pragma once

#include "examples/opal-view/core/edited_scene.h"
#include "examples/opal-view/core/new_light.h"
#include "examples/opal-view/core/orbit_camera.h"
#include "examples/opal-view/core/render_session.h"
#include "examples/opal-view/core/scene_document.h"
#include "examples/opal-view/core/undo_stack.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>

namespace opal::view {

class ViewerModel {
public:
    // `delegate` must outlive the model. The viewport starts at width x height.
    ViewerModel(hd::RenderDelegate& delegate, int width, int height);

    // Opens a scene or asset layer (scene_document.h), replacing the open one; the camera
    // starts at the scene's camera, or framing everything. Throws opal::Error; the open
    // document then stays.
    void open(const std::filesystem::path& file);
    bool isOpen() const { return session_ != nullptr; }
    const std::filesystem::path& file() const { return file_; }
    const scene::Scene& scene() const { return edited_->scene(); }
    const BoundingSphere& bounds() const { return bounds_; }
    std::vector<std::string> takeLoadWarnings();

    // The mesh whose material the panel edits (the first by default) and its material.
    const hd::SdfPath& selectedMesh() const { return selectedMesh_; }
    void selectMesh(const hd::SdfPath& mesh);
    const TranslucentAsset& selectedAsset() const;
    const hd::SdfPath& selectedMaterialPath() const;
    const hd::MaterialDesc& selectedMaterial() const;
    void setSelectedMaterial(const hd::MaterialDesc& desc);
    // material_edit.h's withParameter on the selected material; throws opal::Error.
    void setMaterialParameter(std::string_view parameter, std::span<const double> values);
    void resetMaterial();
    // One of schema/scatter's presets (sigma_s', sigma_a, eta), the specular layer kept;
    // throws opal::Error for an unknown name or one outside the asset's editable range.
    void applyPreset(std::string_view name);

    // Throws opal::Error naming the path for a light the scene does not have.
    const hd::LightDesc& light(const hd::SdfPath& path) const;
    void setLight(const hd::SdfPath& path, const hd::LightDesc& desc);
    void moveLight(const hd::SdfPath& path, const Imath::V3d& position);
    std::optional<hd::SdfPath> selectedLight;  // the light the viewport drags
    // Adds a light at `path` (a new prim path), or under </_OpalView/Lights> with a name of
    // its kind; selects it and returns its path. Throws opal::Error for a bad path.
    hd::SdfPath addLight(NewLightKind kind, const std::optional<hd::SdfPath>& path = std::nullopt);
    // The same for a baked light layer (light_layer.h; named ShadowField1, ...); throws
    // opal::Error naming the file.
    hd::SdfPath addShadowFieldLight(const std::filesystem::path& lightLayer,
                                    const std::optional<hd::SdfPath>& path = std::nullopt);
    void removeLight(const hd::SdfPath& path);
    // A new last element for the light's path; returns the new path (selected if it was).
    hd::SdfPath renameLight(const hd::SdfPath& path, std::string_view name);
    void setLightEnabled(const hd::SdfPath& path, bool enabled);
    bool lightEnabled(const hd::SdfPath& path) const;
    const std::set<hd::SdfPath>& disabledLights() const { return edited_->disabledLights(); }

    // Material and light edits, undone and redone as a whole (the camera is not an edit).
    // While merging (a slider or the light held by the mouse), the edits from the first on
    // are one step.
    void setMergingEdits(bool merging);
    bool undo();  // false when there is nothing to undo
    bool redo();
    // Material or light edits since the document was opened or last saved.
    bool unsaved() const;
    // The window title: the file's name, " *" while unsaved, and its folder.
    std::string title() const;
    // The edited scene as a layer (usda_export.h) through the current camera at the viewport's
    // size with the delegate's settings that differ from their defaults; no longer unsaved.
    void saveScene(const std::filesystem::path& file);

    // Scene time, in the layer's time codes. setTime reads the file's time-varying lights
    // and mesh transforms at `timeCode` (scene_reader.h) and gives flickering lights its
    // seconds; not an edit (nothing to undo or save). Throws opal::Error: a time that is
    // not finite, the file's errors at that time. The free camera is not animated; a used
    // scene camera is.
    void setTime(double timeCode);
    double timeCode() const { return timeCode_; }
    // Whether time changes the picture: time samples, or a flickering light.
    bool animated() const;
    // While playing, advance moves the time on by `seconds` of wall-clock time, looping over
    // the layer's startTimeCode..endTimeCode when it gives them.
    bool playing = false;
    void advance(double seconds);

    // The free camera, which the viewport looks through unless a scene camera is used.
    OrbitCamera camera;
    // The scene's own cameras (not the viewer's), and the one looked through (none: the
    // free camera). A scene camera follows scene time when its transform is animated.
    std::vector<hd::SdfPath> sceneCameras() const;
    const std::optional<hd::SdfPath>& usedCamera() const { return usedCamera_; }
    // Throws opal::Error naming the scene's cameras for a path that is not one of them.
    void useCamera(const hd::SdfPath& path);
    // Back to the free camera, which starts where the scene camera looked from (as a
    // tumble or a dolly does in usdview); the free camera, for moving it.
    OrbitCamera& useFreeCamera();
    // What the viewport looks through as a free camera (roll dropped): for gestures,
    // gizmos and light drags.
    OrbitCamera viewedCamera() const;
    // Each goes to the free camera: everything framed, the selected mesh framed, the
    // camera the document opened with.
    void frameAll();
    void frameSelection();
    void resetCamera();
    void setViewport(int width, int height);
    // The AOVs the renderer writes (empty: every one); the others keep what they last held.
    void setRenderedAovs(std::vector<std::string> aovs) { viewport_.aovs = std::move(aovs); }
    int width() const { return viewport_.width; }
    int height() const { return viewport_.height; }
    double aspect() const { return double(viewport_.width) / viewport_.height; }

    // Once per interface frame: the camera and every edit since go to the session, once
    // the frame of the last submission finished a pass (RenderSession::firstPassDone).
    // Returns the submission's number (RenderSession::submit), 0 when nothing went.
    int update();
    // A render setting for the delegate, checked against its descriptor (setting_text.h;
    // throws opal::Error for an unknown key or a bad value), set by the session's worker
    // before its next sync; the text form is read as the type of the setting's default.
    void setRenderSetting(std::string_view key, const hd::Value& value);
    void setRenderSettingText(std::string_view key, std::string_view value);
    // The value the delegate has, or the one waiting to be set.
    hd::Value renderSetting(const hd::Token& key) const;
    RenderSession& session() const { return *session_; }
    // Renders on `delegate` from now on (which must outlive the model or the next call): the
    // render index, pass and session are torn down and built again on it with the same
    // edited scene, camera, viewport and undo history; the scene's own render settings are
    // applied to it, settings changed on the old delegate are not (they are its own). The
    // reference session stops (showReference again with the new renderer's). Throws
    // opal::Error when the delegate refuses the scene; the model then has no session until
    // the next useDelegate (isOpen() is false), so a host goes back to the old delegate.
    void useDelegate(hd::RenderDelegate& delegate);
    // The A/B wipe's other side: the same scene, camera and settings rendered on
    // `reference` (a second delegate of the plugin, which must outlive the model or the
    // next call) with opal:reference on, in a session of its own that every edit also
    // goes to; null stops it. Throws opal::Error when the delegate has no opal:reference.
    void showReference(hd::RenderDelegate* reference);
    RenderSession* referenceSession() const { return referenceSession_.get(); }
    // Edits submitted and the session settled (converged on the latest scene), the
    // reference's too while it is shown.
    bool settled() const;

private:
    OrbitCamera initialCamera() const;
    hd::SdfPath addSceneLight(std::string name, scene::SceneLight light, const std::optional<hd::SdfPath>& path);
    RenderSettingChanges changedSettings() const;
    // A session on the reference delegate with the delegate's settings, opal:reference on.
    void startReference();
    // Before a material or light edit: the state it changes goes on the undo stack.
    void recordUndo();
    void restore(const EditState& state);

    hd::RenderDelegate* delegate_;  // never null
    scene::AssetCache assets_;
    std::filesystem::path file_;
    std::optional<SceneDocument> document_;
    std::optional<EditedScene> edited_;
    BoundingSphere bounds_;
    hd::SdfPath selectedMesh_;
    Viewport viewport_, submitted_;
    OrbitCamera home_;
    std::optional<hd::SdfPath> usedCamera_;
    std::vector<std::string> loadWarnings_;
    UndoStack<EditState> undo_;
    bool merging_ = false, gestureOpen_ = false;
    long savedRevision_ = 0;
    double timeCode_ = 0.0;
    std::filesystem::path timeSource_;  // the file opened: what time re-reads (a save writes no samples)
    RenderSettingChanges pendingSettings_;  // for the next submission
    hd::RenderDelegate* referenceDelegate_ = nullptr;
    std::unique_ptr<RenderSession> referenceSession_;
    std::unique_ptr<RenderSession> session_;  // last: goes first
};

}  // namespace opal::view
