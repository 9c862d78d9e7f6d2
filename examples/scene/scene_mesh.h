// A translucent mesh in a scene: a prim (typeless, or a Mesh) whose one reference names a
// baked asset layer, `references = @./candle.usda@` (anchored at the scene layer; a
// prim path, if given, must be the asset's default prim). The asset brings the mesh and
// its OpalSubsurfaceAPI data; the scene adds the transformation and a material binding.
#pragma once

#include "examples/scene/asset_cache.h"
#include "examples/scene/prim_reader.h"
#include "examples/scene/scene.h"

#include <filesystem>

namespace opal::scene {

// Whether `prim` is a reference to a baked asset (it authors references).
bool isAssetReference(const usda::Prim& prim);

// Loads the referenced asset through `assets` and places it with `objectToWorld`. Throws
// UsdaError at the reference for anything but one external reference, a file that does
// not exist, an asset that does not load (with readAsset's message), or a prim path
// other than the asset's.
SceneMesh readMesh(PrimReader& reader, const Imath::M44d& objectToWorld, const std::filesystem::path& layerFile,
                   AssetCache& assets);

}  // namespace opal::scene
