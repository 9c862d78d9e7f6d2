// The steps of OpalRenderDelegate::commitResources, each over the render index's prims:
// gather the lights, materials and meshes the last sync left, rebuild the Embree scene when
// geometry changed, and relight each mesh for what changed (translucent_mesh.h lists the
// costs). The frame they fill is what the render thread draws next.
#pragma once

#include "delegate/hd/render_index.h"
#include "delegate/image/renderer.h"
#include "delegate/light.h"
#include "delegate/material_prim.h"
#include "delegate/translucent_mesh.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace opal {

// Every light prim, and every one that synced once as a LightSource by path, its analytic
// light or dome also added to `frame` (a failed first sync leaves version 0: such a light
// is not there yet).
std::vector<OpalLight*> collectLightPrims(const hd::RenderIndex& index);
LightSources collectLights(const hd::RenderIndex& index, Frame& frame);

using MaterialPrims = std::map<hd::SdfPath, const OpalMaterial*>;
MaterialPrims collectMaterials(const hd::RenderIndex& index);
std::vector<TranslucentMesh*> collectMeshes(const hd::RenderIndex& index);

// Whether a mesh was added, removed, moved, shown or hidden since `committed`.
bool geometryChanged(const std::vector<TranslucentMesh*>& meshes, const std::vector<const hd::Rprim*>& committed);
// The visible meshes in one Embree scene. Throws opal::Error naming the mesh that failed.
std::shared_ptr<const RayScene> buildRayScene(const std::vector<TranslucentMesh*>& meshes, CommitStats& stats);

struct RelightOptions {
    bool reference = false;     // opal:reference
    bool raysRebuilt = false;   // the ray scene is new: shadows are stale
};
// Each visible mesh: its lights' E, its material, its radiance, added to frame.meshes;
// hidden meshes let go of theirs. Throws opal::Error naming the mesh (and its light or
// material) that failed.
void relightMeshes(const std::vector<TranslucentMesh*>& meshes, const LightSources& lights,
                   const MaterialPrims& materials, RelightOptions options, Frame& frame, CommitStats& stats,
                   std::vector<std::string>& warnings);

}  // namespace opal
