// The scene delegate of a USDA scene (as UsdImagingDelegate is USD's): it inserts the
// scene's prims into a render index and answers the prims' pulls during sync with the
// descriptions readScene produced. The delegate it feeds is reached only through the
// render index, so any renderer plugin can consume it.
#pragma once

#include "delegate/hd/render_index.h"
#include "delegate/hd/scene_delegate.h"
#include "examples/scene/asset_cache.h"
#include "examples/scene/scene.h"

namespace opal::scene {

class UsdaSceneSource final : public hd::SceneDelegate {
public:
    explicit UsdaSceneSource(Scene scene) : scene_(std::move(scene)) {}

    const Scene& scene() const { return scene_; }
    // A host that edits the scene (a viewer) hands the edited copy over before a sync, from
    // the thread that syncs, and marks what changed dirty. Prims keep their paths. The
    // copy is described at its own timeCode: that is the time flickering lights take.
    void setScene(Scene scene) {
        scene_ = std::move(scene);
        time_ = scene_.timeCode / scene_.timeCodesPerSecond;
    }

    // The scene time in seconds (0 at first) at which time-varying prims are described:
    // a shadow-field light's flicker, and the prims scene.timeVarying names (animated
    // lights, cameras and xformOps), whose descriptions are read again from the scene
    // file at time code seconds * timeCodesPerSecond (their assets through `assets`).
    // Marks what changed dirty in `index`. Throws what readScene throws at that time.
    double time() const { return time_; }
    void setTime(double seconds, hd::RenderIndex& index, AssetCache& assets);

    // Inserts every material and camera and light (Sprims), then every mesh (Rprims).
    // A prim the index refuses (a type the delegate does not support, e.g. a shadow-field
    // light) throws usda::UsdaError at the prim with the index's message.
    void populate(hd::RenderIndex& index) const;

    // Each throws opal::Error for a path the scene has no such prim at.
    hd::MeshDesc mesh(const hd::SdfPath& id) const override;
    hd::MaterialDesc material(const hd::SdfPath& id) const override;
    hd::LightDesc light(const hd::SdfPath& id) const override;
    hd::CameraDesc camera(const hd::SdfPath& id) const override;

private:
    void takeTimeVarying(Scene atTime, hd::RenderIndex& index);

    Scene scene_;
    double time_ = 0.0;
};

}  // namespace opal::scene
