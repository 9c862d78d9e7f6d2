// What a scene layer describes once read (readScene, scene_reader.h): the prims the
// delegate will get, keyed by prim path, each with its description and where it was
// authored. Plain data; UsdaSceneSource serves it to a render index.
#pragma once

#include "delegate/hd/scene_delegate.h"
#include "examples/scene/render_settings_prim.h"
#include "schema/usd/usda_location.h"

#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace opal::scene {

struct SceneMesh {
    hd::MeshDesc desc;
    // The referenced asset layer, resolved; for a Mesh applying OpalSubsurfaceAPI through
    // an over-layer (applied_asset_mesh.h), the layer that authored its sidecar.
    std::filesystem::path assetFile;
    usda::SourceLocation where;  // the prim
    bool applied = false;        // the latter: not a prim referencing an asset layer
};

struct SceneMaterial {
    hd::MaterialDesc desc;
    usda::SourceLocation where;
};

struct SceneLight {
    hd::Token primType;  // hd::PrimType::SphereLight, ...
    hd::LightDesc desc;
    usda::SourceLocation where;
};

struct SceneCamera {
    hd::CameraDesc desc;
    usda::SourceLocation where;
};

struct Scene {
    std::filesystem::path file;             // the layer, as given
    std::string upAxis = "Y";               // layer metadata upAxis: "Y" or "Z"
    std::optional<double> metersPerUnit;    // layer metadata, when authored
    double timeCodesPerSecond = 24.0;       // layer metadata (USD's fallback 24)
    double timeCode = 0.0;                  // the time the descriptions were read at
    std::optional<double> startTimeCode, endTimeCode;  // layer metadata, when authored
    // The prims whose descriptions change with time (they, or an ancestor's xformOps,
    // have more than one time sample): lights, cameras and meshes.
    std::set<hd::SdfPath> timeVarying;
    std::map<hd::SdfPath, SceneMesh> meshes;
    std::map<hd::SdfPath, SceneMaterial> materials;
    std::map<hd::SdfPath, SceneLight> lights;
    std::map<hd::SdfPath, SceneCamera> cameras;
    std::optional<SceneRenderSettings> renderSettings;
    std::vector<std::string> warnings;      // each starts with file:line:column
};

}  // namespace opal::scene
