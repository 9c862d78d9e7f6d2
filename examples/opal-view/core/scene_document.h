// What opal-view opens: a scene layer (examples/SCENES.md) as it is, or a baked asset layer
// alone, staged with what a turntable needs (a camera framing it, a key light, the asset's
// default material). Either way the viewer adds its own prims under /_OpalView: the free
// camera it renders through, and an editable material for every mesh the file leaves
// unbound (the asset's default material with the delegate's default specular layer, so
// the picture does not change until the artist edits it).
#pragma once

#include "examples/scene/asset_cache.h"
#include "examples/scene/scene.h"

#include <filesystem>
#include <optional>

namespace opal::view {

inline const hd::SdfPath ViewerRoot = "/_OpalView";
inline const hd::SdfPath ViewCameraPath = "/_OpalView/Camera";
inline const hd::SdfPath KeyLightPath = "/_OpalView/KeyLight";

struct SceneDocument {
    scene::Scene scene;                    // with the viewer's prims
    std::optional<hd::SdfPath> sceneCamera;  // the camera the file renders through, if any
    bool assetOnly = false;                // the file was an asset layer
};

// Whether `file` is a baked asset layer: its default prim (else its first root prim)
// applies OpalSubsurfaceAPI. Throws the USDA reader's errors.
bool isAssetLayer(const std::filesystem::path& file);

// Throws opal::Error naming the file: the scene reader's and the asset reader's errors, a
// scene that already uses </_OpalView>, or one without a translucent mesh.
SceneDocument loadDocument(const std::filesystem::path& file, scene::AssetCache& assets);

}  // namespace opal::view
