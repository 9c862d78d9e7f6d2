// Direct integration of an emitter's irradiance at a surface point: the accuracy reference
// the shadow-field light is measured against (tests/fieldlight, `opal-bench shadow-field`).
// For a point x with unit normal n and the emitter placed by a translation `at` (its light
// frame shifted to world), over the cone of the emitter's bounding sphere seen from x,
//     E = integral L(w) max(0, n.w) V(w) dw,
// by side x side directions stratified in (cos theta, phi) about the cone's axis, each
// traced with Embree against the emitter's own parts (EmitterScene, what it sees is the
// radiance the part emits toward x) and, up to where it hits the emitter, against the
// blockers from x + offset n (V). Independent of the field: no maps, no interpolation.
// relativeRmse is the one accuracy figure the tests and the bench quote against it.
#pragma once

#include "bake/light/emitter_scene.h"
#include "raytrace/ray_scene.h"

#include <Imath/ImathVec.h>

#include <span>

namespace opal {

// RGB irradiance at x; blockers may be null (no shadows). side >= 1.
Imath::V3d directIrradiance(const EmitterScene& emitter, const RayScene* blockers, const Imath::V3d& at,
                            const Imath::V3d& x, const Imath::V3d& n, double offset, int side = 32);

// sqrt(sum |estimate - direct|^2 / sum |direct|^2) over the points and channels: an
// estimate of E (the shadow field's) against directIrradiance at the same points. When
// every direct value is 0: 0 for an estimate that is 0 too, infinity for one with light.
// Throws opal::Error when the counts differ.
double relativeRmse(std::span<const Imath::V3d> estimate, std::span<const Imath::V3d> direct);

}  // namespace opal
