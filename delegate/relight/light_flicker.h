// A light's flicker at a scene time (docs/ARCHITECTURE.md#flicker): `opal:flicker:amplitude`
// A, `opal:flicker:frequency` f (Hz) and `opal:flicker:seed` s give
//     intensity(t) = max(0, 1 + A n_0(f t)),   offset(t) = A (n_1(f t), n_2(f t) / 2, n_3(f t)) / 4,
// with n_j smooth value noise in [-1, 1] (two octaves of cubic-interpolated lattice values
// hashed from s and j). The offset is in emitter radii, in the light's frame (the flame
// sways sideways more than it bobs). A = 0 is no flicker (exactly 1 and no offset); the
// same (A, f, s, t) always gives the same values, on every machine.
#pragma once

#include "delegate/hd/scene_delegate.h"

#include <Imath/ImathVec.h>

namespace opal {

struct FlickerState {
    double intensity = 1.0;      // multiplies the light's emission
    Imath::V3d offset{0.0};      // emitter radii, light frame
};

// Throws opal::Error when amplitude or frequency is negative or not finite, or the time is
// not finite.
FlickerState lightFlicker(const hd::LightFlicker& flicker, double time);

}  // namespace opal
