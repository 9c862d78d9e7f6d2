// The emitted radiance of a UsdLux light, L_e = color * intensity * 2^exposure (times the
// black body colour of inputs:colorTemperature when it is enabled; docs/ARCHITECTURE.md
// #light-emission), formed in double and checked before any of it is stored in float, and the bounds that keep every
// radiometric value the delegate forms from it finite.
//
// Why these bounds: the delegate sums light in float. A light's L_e is at most
// kMaxEmittedRadiance (1e20, far beyond any physical source in any unit Opal's scenes use);
// a dome's texels times its L_e obey the same bound. The irradiance one light gives one
// sample, E_perp = I / d^2, grows without bound as a point light nears a surface, so
// AnalyticLight::incidence saturates it at kMaxSampleIrradiance (1e25). With transfer entries of
// order one (b_k(r) A_i, mm^-2 times mm^2) and at most 2^31 samples, every sum the engine
// forms then stays below 1e25 * 2^31 * 10 < 3.4e38, the largest float.
#pragma once

#include "delegate/hd/scene_delegate.h"
#include "schema/scatter/rgb.h"

namespace opal {

inline constexpr double kMaxEmittedRadiance = 1e20;
inline constexpr double kMaxSampleIrradiance = 1e25;

// L_e per channel. Throws opal::Error naming the attributes (inputs:intensity,
// inputs:exposure, inputs:color, inputs:colorTemperature) and their values when one is not
// finite, the color or intensity is negative, an enabled temperature is outside 500 to
// 40000 K, or the product exceeds kMaxEmittedRadiance in any channel.
Rgb emittedRadiance(const hd::LightDesc& desc);

}  // namespace opal
