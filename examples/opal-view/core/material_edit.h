// Material edits as the viewer offers them: one parameter at a time, within what the
// mesh's baked asset supports (its editable range; roughness in [0, 1]), and the reset to
// what the bake recorded.
#pragma once

#include "delegate/hd/scene_delegate.h"

#include <span>
#include <string_view>

namespace opal::view {

// The asset's default coefficients and eta with the delegate's default specular layer:
// what a mesh without a material binding renders with.
hd::MaterialDesc bakedDefault(const TranslucentAsset& asset);

// `desc` with `parameter` ("sigma_s" or "sigma_a": three values R G B in mm^-1; "albedo"
// (total diffuse reflectance, 0 to 1) or "mfp" (diffuse mean free path, mm): three values
// R G B, the other of the two and eta kept, converted to sigma_s' and sigma_a by
// schema/scatter's fromArtist; "eta" or "roughness": one) set. Throws opal::Error naming
// the parameter, the channel, the value and the allowed interval when a value lies
// outside the asset's range (for albedo and mfp: the sigma it converts to).
hd::MaterialDesc withParameter(hd::MaterialDesc desc, std::string_view parameter, std::span<const double> values,
                               const TranslucentAsset& asset);

}  // namespace opal::view
