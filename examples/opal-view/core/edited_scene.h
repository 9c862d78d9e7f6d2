// The interface's copy of the scene and what it changed since the render session last
// took it: every edit replaces one prim's description and records the dirty bits a render
// index needs for it (a slider dragged over many frames accumulates into one sync).
#pragma once

#include "delegate/hd/change_tracker.h"
#include "examples/scene/scene.h"

#include <map>

namespace opal::view {

using DirtyPrims = std::map<hd::SdfPath, hd::DirtyBits>;

class EditedScene {
public:
    explicit EditedScene(scene::Scene scene) : scene_(std::move(scene)) {}

    const scene::Scene& scene() const { return scene_; }

    // Each throws opal::Error naming the path when the scene has no such prim.
    void setMaterial(const hd::SdfPath& path, const hd::MaterialDesc& desc);
    void setLight(const hd::SdfPath& path, const hd::LightDesc& desc);
    void setCamera(const hd::SdfPath& path, const hd::CameraDesc& desc);

    bool changed() const { return !dirty_.empty(); }
    // What changed since the last call, and clears it.
    DirtyPrims takeChanges();

private:
    scene::Scene scene_;
    DirtyPrims dirty_;
};

// The world-space position of a light (its transform's translation).
Imath::V3d lightPosition(const hd::LightDesc& light);
// The light moved to `position`, its orientation kept.
hd::LightDesc movedLight(hd::LightDesc light, const Imath::V3d& position);

}  // namespace opal::view
