// A local light's source radiance field (Zhou et al. 2005, "Precomputed shadow fields for
// dynamic scenes"; docs/ARCHITECTURE.md#shadow-field): incident-radiance cube maps at
// sample points on concentric spheres around the emitter, each map Haar compressed.
//
// Frame and units: the light's own frame (right-handed, +Y up), lengths in millimetres.
// The spheres are centred on `centre`; shell j has radius radii[j] (strictly ascending).
// The sample points of a shell are the directions through the texel centres of a cube map
// of face size `directionFaceSize` (CubeMapLayout order), so sample point i of shell j is
// centre + radii[j] * CubeMapLayout(directionFaceSize).direction(i), and its map is number
// j * directionsPerShell() + i. Each map is a cube map of face size `mapFaceSize` of
// incident radiance (RGB, scene-linear, the emitter's radiance units) stored as the
// orthonormal Haar coefficients of its 6 faces (haarForwardCharts over
// CubeMapLayout::charts(), 3 interleaved channels), of which the kept ones are listed in
// CSR form: map m keeps coefficients offsets[m] .. offsets[m+1], at cube-map positions
// indices[k] (strictly ascending within a map), with values[3k .. 3k+2] (RGB).
#pragma once

#include "schema/asset/emitter_views.h"

#include <Imath/ImathVec.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace opal {

struct ShadowField {
    std::string name;                  // what was baked, e.g. "flame" (at most 4096 bytes)
    Imath::V3d centre{0.0};            // of the shells, light frame, mm
    double emitterRadius = 0.0;        // the emitter's bounding sphere about centre, mm
    std::vector<double> radii;         // shell radii, mm, strictly ascending, > emitterRadius
    std::uint32_t directionFaceSize = 16;
    std::uint32_t mapFaceSize = 32;
    // The compression rule: each map keeps its largest coefficients (by RGB squared norm)
    // until they hold at least this fraction of the map's energy.
    double keptEnergy = 1.0;
    std::optional<std::uint64_t> bakeId;  // identifies the bake (same inputs, same id)

    std::vector<std::uint64_t> offsets;   // maps() + 1 entries
    std::vector<std::uint32_t> indices;   // kept coefficient positions, < mapTexels()
    std::vector<float> values;            // 3 per kept coefficient, RGB
    // The emitter as a camera sees it (emitter_views.h; chunk VIEW, optional: empty in a
    // sidecar baked before it existed).
    EmitterViews views;

    std::uint32_t shells() const { return std::uint32_t(radii.size()); }
    std::uint32_t directionsPerShell() const { return 6 * directionFaceSize * directionFaceSize; }
    std::uint32_t mapTexels() const { return 6 * mapFaceSize * mapFaceSize; }
    std::uint64_t maps() const { return std::uint64_t(shells()) * directionsPerShell(); }
};

}  // namespace opal
