// Basic vocabulary of Opal's Hydra-style API (delegate/hd): prim paths, tokens, values.
// Like Hydra's hd library, this layer is what hosts and render delegates share; a host
// never sees a delegate's concrete classes (it loads them through plugin/'s registry).
#pragma once

#include <cstdint>
#include <string>
#include <variant>

namespace opal::hd {

using SdfPath = std::string;  // an absolute prim path, e.g. "/World/Candle"
using Token = std::string;

// A render setting or a generic prim parameter.
using Value = std::variant<std::monostate, bool, int, double, std::string>;

// Prim type tokens, named after the USD schema each stands for.
namespace PrimType {
inline const Token TranslucentMesh = "translucentMesh";  // Mesh with OpalSubsurfaceAPI
inline const Token Camera = "camera";                    // UsdGeomCamera
inline const Token Material = "material";                // Opal material override
inline const Token SphereLight = "sphereLight";          // UsdLuxSphereLight (+ shaping: spot)
inline const Token DistantLight = "distantLight";        // UsdLuxDistantLight
inline const Token DomeLight = "domeLight";              // UsdLuxDomeLight
inline const Token ShadowFieldLight = "opalShadowFieldLight";
inline const Token RenderBuffer = "renderBuffer";
}  // namespace PrimType


}  // namespace opal::hd
