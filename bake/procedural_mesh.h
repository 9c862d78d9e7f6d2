// Control meshes made in code: the built-in candle of the main job (`opal-bake
// builtin:candle`) and its wick (`opal-bake builtin:wick`), and surfaces of revolution in
// general. Units: millimetres; +Y up; the candle's base centre is the origin, and the wick
// is placed in the same frame, so both assets stand at the same scene position.
#pragma once

#include "bake/control_mesh.h"

#include <Imath/ImathVec.h>

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace opal {

// Revolves a profile of (radius, height) points about +Y with `segments` sectors. A point
// with radius 0 is a pole (a triangle fan); the others become rings, joined by quads.
// The profile runs from the bottom to the top, so faces wind counter-clockwise seen from
// outside. Ring k's sector s lies at the angle 2 pi s / segments counter-clockwise about
// +Y from +X (a pole is one vertex).
ControlMesh makeSurfaceOfRevolution(std::span<const Imath::V2f> profile, int segments, std::string name);

// The built-in candle's sizes (of the control mesh; Catmull-Clark rounds the lip and moves
// the surface inward by a fraction of a millimetre).
struct CandleSize {
    static constexpr float radius = 20.0f;      // the pillar's outer wall: 40 mm across
    static constexpr float rimHeight = 80.0f;   // the rim's crest above the base, its mean around the circle
    static constexpr float rimWobble = 0.6f;    // the crest rises and falls around the circle by at most this
    static constexpr float rimInner = 18.2f;    // the crest's inner edge; the inner wall falls from it to the pool
    static constexpr float poolDepth = 5.0f;    // the pool's centre lies this far below the crest's mean
    static constexpr float poolCentre = rimHeight - poolDepth;  // 75 mm above the base
    static constexpr int segments = 32;         // sectors around the axis
};

// A pillar candle that has burnt for a while: a straight wax wall, a rounded base edge, a
// thin raised rim (about 2 mm thick at its foot) whose crest wobbles a little around the
// circle, and a concave melt pool, deepest at the centre (CandleSize).
ControlMesh makeCandle();

// The built-in wick's sizes, in the candle's frame. It stands at the pool's centre, its
// base `depth` below the pool and its tip `height` above it; its upper part bends toward
// +X (charred wicks curl), the tip `lean` off the axis.
struct WickSize {
    static constexpr float radius = 0.8f;
    static constexpr float height = 9.0f;
    static constexpr float depth = 2.5f;
    static constexpr float lean = 1.5f;
    static constexpr int segments = 8;
};

// A thin, slightly bent cylinder with rounded ends (WickSize), closed.
ControlMesh makeWick();

// The meshes `opal-bake` knows by name: the mesh `input` names ("builtin:candle",
// "builtin:wick"), or nullopt when `input` is not "builtin:..." (a file). Throws
// opal::Error for an unknown "builtin:" name.
std::optional<ControlMesh> builtinMesh(std::string_view input);
std::string builtinMeshNames();

}  // namespace opal
