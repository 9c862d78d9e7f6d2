// The emitter a `opal-bake light SPEC` describes. SPEC is `KIND:KEY=VALUE,KEY=VALUE,...`
// (no spaces; lengths in mm; radiance `L` for grey or `R/G/B`, scene-linear):
//   sphere:radius=A[,radiance=L]
//   disk:radius=A[,radiance=L]                       (emits toward -Y)
//   rectangle:width=W,height=H[,radiance=L]          (in XZ, emits toward -Y)
//   lamp:radius=A,height=H[,shade_radius=S][,shade_height=T][,radiance=L]
//                                                    (shade defaults 1.5 A and 1.25 H)
//   mesh:file=PATH[,radiance=L]                      (PATH relative to the working folder)
//   flame:height=H,radius=A[,core_k=K][,rim_k=K][,luminance=Y]
// radiance defaults to 1. Every error names the spec and the key.
#pragma once

#include "bake/light/emitter.h"

#include <string>
#include <string_view>

namespace opal {

// Throws opal::Error: unknown kind or key, a key given twice, a missing required key, a
// value that is not a finite number or is out of range, an unreadable mesh file.
Emitter parseLightSpec(std::string_view spec);

// The kinds and their keys, for help texts.
std::string lightSpecHelp();

}  // namespace opal
