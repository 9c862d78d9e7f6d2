// Bakes an emitter's source radiance field (schema/asset/shadow_field.h): for every sample
// point on every shell, an incident-radiance cube map (incident_radiance.h), Haar
// compressed (cube_map_compression.h). Shell radii are spaced geometrically from
// innerScale to outerScale times the emitter's bounding-sphere radius a, about its
// centre: r_j = innerScale a (outerScale / innerScale)^(j / (shells - 1)).
// The stored values are rounded as the sidecar stores them (binary16 planes), and the
// compression error reported includes that rounding. Deterministic: the same emitter and
// settings give the same field, whatever the thread count.
#pragma once

#include "bake/light/emitter.h"
#include "bake/progress.h"
#include "schema/asset/shadow_field.h"

#include <cstdint>

namespace opal {

struct FieldSettings {
    std::uint32_t shells = 16;
    std::uint32_t directionFaceSize = 16;  // 6 x 16 x 16 sample points per shell
    std::uint32_t mapFaceSize = 32;        // cube maps of 6 x 32 x 32 texels
    std::uint32_t raysPerTexelSide = 4;    // 4 x 4 stratified rays per texel
    double innerScale = 1.05;              // inner shell radius / emitter radius
    double outerScale = 8.0;               // outer shell radius / emitter radius
    double keptEnergy = 0.9999;            // per map: relative L2 error <= 1%
    std::uint32_t viewFaceSize = 4;        // the emitter's views (emitter_views.h): 6 x 4 x 4
    std::uint32_t viewImageSize = 64;      // of 64 x 64 pixels each
    std::uint64_t seed = 1;
};

struct FieldBakeStats {
    std::uint64_t maps = 0, coefficients = 0, rays = 0;
    // Relative L2 error over texels of the stored maps against the rendered ones
    // (compression and binary16 rounding): the worst map, the RMS over maps that see any
    // light, and the whole field's (sqrt of total error energy / total energy).
    double worstMapError = 0.0, rmsMapError = 0.0, fieldError = 0.0;
    double seconds = 0.0;
};

// Throws opal::Error for settings out of range (shells < 2, face sizes not powers of
// two, scales not 1 < inner < outer, keptEnergy outside (0, 1]), Cancelled when cancelled.
ShadowField bakeShadowField(const Emitter& emitter, const FieldSettings& settings, ProgressSink* progress,
                            const CancelToken& cancel, FieldBakeStats* stats = nullptr);

// The shell radii the bake uses for an emitter of bounding radius `emitterRadius`.
std::vector<double> shellRadii(double emitterRadius, const FieldSettings& settings);

}  // namespace opal
