// A translucent mesh that is a Mesh prim applying OpalSubsurfaceAPI itself, as a scene
// gets it by sublayering an asset's over-layer (opal-bake --apply-to) over the user's
// layer (examples/scene/layer_stack.h): the composed prim carries the render mesh, the
// Opal attributes and the sidecar, its sidecar path anchored at the scene layer. The
// user's own Mesh attributes (normals, primvars, creases, ...) are accepted and not used;
// orientation must be rightHanded and subdivisionScheme "none", as the over-layer writes
// them (a weaker layer's value here means the over-layer is not the strongest).
#pragma once

#include "examples/scene/asset_cache.h"
#include "examples/scene/prim_reader.h"
#include "examples/scene/scene.h"

#include <filesystem>

namespace opal::scene {

// Whether `prim` is a Mesh that applies OpalSubsurfaceAPI.
bool appliesSubsurface(const usda::Prim& prim);

// Loads the prim's asset through `assets` and places it with `objectToWorld`. Throws
// UsdaError at the prim naming it for another applied schema, the checks above, or an
// asset that does not load (with readAsset's message).
SceneMesh readAppliedAssetMesh(PrimReader& reader, const Imath::M44d& objectToWorld,
                               const std::filesystem::path& layerFile, AssetCache& assets);

}  // namespace opal::scene
