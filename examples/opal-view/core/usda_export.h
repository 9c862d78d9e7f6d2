// The viewer's edited scene written back as a scene layer (examples/SCENES.md) that
// opal-render renders as the viewer shows it: every mesh, material, light and camera at its
// path, placed by its world matrix (`!resetXformStack!` + `xformOp:transform`, so the
// groups above it are plain typeless prims), a RenderSettings prim naming the viewer's
// camera and resolution and carrying the delegate's settings, and asset paths re-anchored
// at the new layer. The viewer's own prims (under </_OpalView>, a root a scene may not use
// when the viewer opens it) move to a root the scene does not use, so the saved layer opens
// again. A material the artist did not edit keeps the prim the scene authored (a preset or
// artist parameters: exact), an edited one is written as opal:sigmaSPrime + opal:sigmaA.
#pragma once

#include "examples/scene/scene.h"
#include "schema/usd/usda_layer.h"

#include <filesystem>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace opal::view {

struct SceneExport {
    scene::Scene scene;                           // as edited, the viewer's prims included
    std::set<hd::SdfPath> disabledLights;         // in scene.lights, written invisible
    std::map<hd::SdfPath, usda::Prim> authoredMaterials;  // written as authored instead
    hd::SdfPath camera;                           // the camera the layer renders through
    int width = 0, height = 0;                    // its resolution
    std::vector<std::pair<hd::Token, hd::Value>> settings;  // delegate settings to author
};

// The layer `target` should hold. Throws opal::Error for a value the layer cannot hold.
usda::Layer exportLayer(const SceneExport& scene, const std::filesystem::path& target);

// exportLayer written atomically (schema/usd/usda_writer.h); errors name `target`.
void saveSceneLayer(const SceneExport& scene, const std::filesystem::path& target);

// The Material prims of `file` (a scene layer) by path, as authored; empty for an asset layer.
std::map<hd::SdfPath, usda::Prim> authoredMaterialPrims(const std::filesystem::path& file);

}  // namespace opal::view
