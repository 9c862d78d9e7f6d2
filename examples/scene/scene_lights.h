// The scene's lights (UsdLux, plus Opal's OpalShadowFieldLight) read into the delegate's
// hd::LightDesc. Every light takes LightAPI's inputs:intensity (>= 0), inputs:exposure,
// inputs:color (>= 0), inputs:enableColorTemperature, inputs:colorTemperature (kelvin,
// 500 to 40000) and inputs:normalize with USD's fallbacks; then
//   SphereLight           inputs:radius, treatAsPoint, inputs:shaping:cone:angle and
//                         inputs:shaping:cone:softness (also spelt shaping:cone:*, as
//                         before USD 21.05); a cone angle makes it a spot light
//   DistantLight          inputs:angle; intensity falls back to 50000, as in UsdLux
//   DomeLight             inputs:texture:file (a lat-long image, anchored at the layer;
//                         its colorSpace metadata names the image's color space),
//                         inputs:texture:format "latlong" (or the fallback "automatic")
//   OpalShadowFieldLight  opal:field (the light asset), passed through to the delegate;
//                         opal:flicker:amplitude (0..1), opal:flicker:frequency (Hz,
//                         0..1000), opal:flicker:seed
#pragma once

#include "delegate/hd/scene_delegate.h"
#include "examples/scene/prim_reader.h"

#include <filesystem>
#include <optional>
#include <string_view>

namespace opal::scene {

// The largest values the reader accepts for the shape inputs (from 0; radius has none):
// a spot's cone angle and softness, a distant light's angular diameter (degrees).
inline constexpr double MaxConeAngle = 180.0, MaxConeSoftness = 1.0, MaxDistantAngle = 180.0;

// The delegate prim type and light kind of a USD light type; nullopt for other types.
struct LightType {
    hd::Token primType;
    hd::LightKind kind;
};
std::optional<LightType> lightTypeOf(std::string_view usdTypeName);

// Reads the light `reader` describes (its type must be one lightTypeOf knows), placed
// by `objectToWorld`; files are resolved against `layerFile` and must exist. Throws
// UsdaError at the attribute at fault.
// `base` holds what a referenced light layer authored (referencedLight): the prim's own
// attributes are stronger, as in USD.
hd::LightDesc readLight(PrimReader& reader, const Imath::M44d& objectToWorld, const std::filesystem::path& layerFile,
                        hd::LightDesc base = {});

// A light prim that references a baked light layer (`def OpalShadowFieldLight "Flame"
// (references = @./flame.usda@)`, what `opal-bake light` writes): that layer's light prim
// (the reference's prim path, else its defaultPrim) read as a light, its files resolved
// against its own layer. Throws UsdaError at the reference (no such file, more than one
// reference, a prim of another type) or inside the light layer (its own errors). The
// light layer's time samples are read at `timeCode`.
struct ReferencedLight {
    hd::LightDesc desc;
    bool timeVarying = false;  // the referenced prim has animated attributes
};
ReferencedLight referencedLight(PrimReader& reader, const std::filesystem::path& layerFile, double timeCode);

}  // namespace opal::scene
