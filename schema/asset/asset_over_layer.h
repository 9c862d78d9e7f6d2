// A baked asset as an over-layer on a prim of the user's own layer (opal-bake --apply-to):
// `over` prims down to the Mesh prim at `primPath`, which applies OpalSubsurfaceAPI
// (prepended) with every attribute the asset layer (asset_layer.h) gives its prim, and
// overrides the prim's mesh with the render mesh the sidecar matches: points, normals,
// extent, faceVertexCounts, faceVertexIndices, orientation, subdivisionScheme "none"
// (and primvars:displayColor), with an empty holeIndices (the bake left the holes out). The
// user's other primvars keep the control mesh's counts, which USD hosts then ignore. It
// defines no prim and takes no type, kind or transform: sublayered over the user's layer,
// the user's def keeps its type, hierarchy and xformOps, and the asset, baked in the
// prim's own space, lands where the prim is.
#pragma once

#include "schema/asset/translucent_asset.h"
#include "schema/usd/usda_layer.h"

#include <string>

namespace opal {

// Throws opal::Error unless `primPath` is absolute and ends in asset.name (the bake names
// an --apply-to asset after its prim, so that the composed prim and the sidecar agree).
usda::Layer assetToOverLayer(const TranslucentAsset& asset, const std::string& sidecarAssetPath,
                             const std::string& primPath);

}  // namespace opal
