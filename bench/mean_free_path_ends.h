// The two ends of a baked asset's editable range by mean free path, the materials
// `opal-bench accuracy` measures beside the asset's default. The mean free path is
// ell = 1 / sigma_t' with sigma_t' = sigma_s' + sigma_a; over the range's box
// [sigma_s' min, max] x [sigma_a min, max] (the same box for every channel) it falls as
// either coefficient grows, so the shortest lies at the corner where both are at their
// maximum and the longest where both are at their minimum, in every channel alike.
#pragma once

#include "schema/asset/translucent_asset.h"
#include "schema/scatter/material.h"

#include <string>
#include <vector>

namespace opal::bench {

// Per channel 1 / (sigma_s' + sigma_a), in mm.
Rgb meanFreePath(const Material& material);

// The range's materials of shortest and longest mean free path, with the given eta (the
// default material's, so that only the scattering changes). Throws opal::Error when the
// range is invalid (EditableRange::validate) or eta lies outside it.
Material shortestMeanFreePath(const EditableRange& range, double eta);
Material longestMeanFreePath(const EditableRange& range, double eta);

// The materials the benches measure, by name: "default" (the asset's), "short" and "long"
// (the ends above, at the default's eta).
inline const std::vector<std::string> kEndMaterials = {"default", "short", "long"};
inline constexpr const char* kEndMaterialsHelp =
    "materials (repeatable): the asset's default, and the shortest and longest mean free path of its editable range";
Material materialNamed(const std::string& name, const TranslucentAsset& asset);

}  // namespace opal::bench
