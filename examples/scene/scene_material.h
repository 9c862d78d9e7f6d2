// A scene's Material prim: Opal's material override for the meshes bound to it
// (rel material:binding). The subsurface coefficients come from exactly one of
//   opal:preset (token)                              a Jensen et al. 2001 measured material
//   opal:sigmaSPrime + opal:sigmaA (color3f, mm^-1)  the coefficients themselves
//   opal:albedo + opal:meanFreePath (color3f, mm)    the artist parameterization
// with opal:eta (float, in the dipole's range [1, 3], see dipole.h) overriding the preset's or default 1.3; opal:specular
// (bool) and opal:specularRoughness (float in [0, 1]) set the specular layer.
#pragma once

#include "delegate/hd/scene_delegate.h"
#include "examples/scene/prim_reader.h"

#include <string>

namespace opal::scene {

// Throws UsdaError at the attribute at fault: no or two parameterizations, half of a
// pair, an unknown preset, a coefficient that is not positive and finite, an albedo
// outside (0, 1), eta outside [1, 3], a roughness outside [0, 1], or a transformation op.
hd::MaterialDesc readMaterial(PrimReader& reader);

// "marble, skin1, ...": the preset names, for messages.
std::string presetNames();

}  // namespace opal::scene
