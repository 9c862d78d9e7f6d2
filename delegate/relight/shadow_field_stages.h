// What one ShadowFieldLight::arrivals call did, for `opal-bench shadow-field`: the time of
// each stage in thread-milliseconds summed over the workers (a stage's share of the wall
// time is its share of the sum), and counts. Filled only when a caller asks for it: timing
// reads the clock a few times per sample.
#pragma once

#include <cstdint>

namespace opal {

struct ShadowFieldStages {
    // setup: the sample into the light's frame and the stencil; interpolation:
    // the stencil's weighted sparse maps summed; cosine: clamp, texel cosine integrals and
    // visibility blocks; visibility: the occlusion rays; far field: the samples beyond the
    // outer sphere (a point light, its one ray included).
    double setupMs = 0.0, interpolationMs = 0.0, cosineMs = 0.0, visibilityMs = 0.0, farFieldMs = 0.0;
    std::uint64_t samples = 0;
    std::uint64_t beyond = 0;  // beyond the outer sphere: the far-field point light
    std::uint64_t facingAway = 0;  // the emitter wholly behind the tangent plane: unlit, skipped
    std::uint64_t terms = 0;   // sparse map terms added
    std::uint64_t texels = 0;  // distinct texels touched
    std::uint64_t rays = 0, blocked = 0;

    ShadowFieldStages& operator+=(const ShadowFieldStages& o) {
        setupMs += o.setupMs;
        interpolationMs += o.interpolationMs;
        cosineMs += o.cosineMs;
        visibilityMs += o.visibilityMs;
        farFieldMs += o.farFieldMs;
        samples += o.samples;
        beyond += o.beyond;
        facingAway += o.facingAway;
        terms += o.terms;
        texels += o.texels;
        rays += o.rays;
        blocked += o.blocked;
        return *this;
    }
    double totalMs() const { return setupMs + interpolationMs + cosineMs + visibilityMs + farFieldMs; }
};

}  // namespace opal
