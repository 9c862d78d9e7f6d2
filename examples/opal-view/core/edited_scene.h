// The interface's copy of the scene and what it changed since the render session last
// took it: every edit replaces one prim's description and records the dirty bits a render
// index needs for it (a slider dragged over many frames accumulates into one sync). Lights
// can be added, removed, renamed and disabled (kept, but left out of what is rendered);
// the material and light edits together are an EditState that undo restores.
#pragma once

#include "delegate/hd/change_tracker.h"
#include "examples/scene/scene.h"

#include <map>
#include <set>

namespace opal::view {

using DirtyPrims = std::map<hd::SdfPath, hd::DirtyBits>;

// What undo and redo restore: every material and light (disabled ones included), and the
// revision: the edit that produced it, so a document knows whether it is back where it
// was saved.
struct EditState {
    std::map<hd::SdfPath, scene::SceneMaterial> materials;
    std::map<hd::SdfPath, scene::SceneLight> lights;
    std::set<hd::SdfPath> disabledLights;
    long revision = 0;
};

class EditedScene {
public:
    explicit EditedScene(scene::Scene scene) : scene_(std::move(scene)) {}

    // Every light, the disabled ones included.
    const scene::Scene& scene() const { return scene_; }
    // What the renderer gets: the scene without its disabled lights.
    scene::Scene renderedScene() const;
    const std::set<hd::SdfPath>& disabledLights() const { return disabled_; }

    // Each throws opal::Error naming the path when the scene has no such prim. Material and
    // light edits take a new revision.
    void setMaterial(const hd::SdfPath& path, const hd::MaterialDesc& desc);
    void setLight(const hd::SdfPath& path, const hd::LightDesc& desc);
    void setCamera(const hd::SdfPath& path, const hd::CameraDesc& desc);
    // The scene at another time code: the time-varying lights, cameras and mesh transforms take
    // their values from `atTime` (the file read at that time; null when nothing in it is
    // time-varying) and flickering lights the time in seconds. Not an edit: no revision.
    void setTime(const scene::Scene* atTime, double timeCode);

    // Throws opal::Error for a path that is not a new prim path of the scene (prim_path.h).
    void addLight(const hd::SdfPath& path, scene::SceneLight light);
    void removeLight(const hd::SdfPath& path);
    // Moves the light to `to` (a new prim path), keeping whether it is enabled.
    void renameLight(const hd::SdfPath& from, const hd::SdfPath& to);
    void setLightEnabled(const hd::SdfPath& path, bool enabled);

    EditState state() const;
    // Back to `state` (an earlier state() of this scene), dirtying what differs.
    void restore(const EditState& state);
    long revision() const { return revision_; }

    // A prim edited, or lights added, removed, renamed, enabled or disabled.
    bool changed() const { return !dirty_.empty() || lightsChanged_; }
    // What changed since the last call, and clears it.
    DirtyPrims takeChanges();

private:
    void edited() { revision_ = ++lastRevision_; }
    void lightsChanged() {
        lightsChanged_ = true;
        edited();
    }

    scene::Scene scene_;
    std::set<hd::SdfPath> disabled_;
    DirtyPrims dirty_;
    long revision_ = 0, lastRevision_ = 0;
    bool lightsChanged_ = false;  // the set of rendered lights may differ
};

// Field by field: whether rendering one or the other can differ.
bool sameMaterial(const hd::MaterialDesc& a, const hd::MaterialDesc& b);
bool sameLight(const hd::LightDesc& a, const hd::LightDesc& b);

// The world-space position of a light (its transform's translation).
Imath::V3d lightPosition(const hd::LightDesc& light);
// The light moved to `position`, its orientation kept.
hd::LightDesc movedLight(hd::LightDesc light, const Imath::V3d& position);

}  // namespace opal::view
