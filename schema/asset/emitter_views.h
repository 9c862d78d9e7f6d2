// How a local light's emitter looks from outside (docs/ARCHITECTURE.md#shadow-field-light):
// what a camera ray that passes through it sees, baked beside its shadow field because the
// field's cube maps are too coarse (and Haar-blocky) to be looked at.
//
// V = 6 D^2 view directions v_k, the texel-centre directions of a cube map of face size D
// (cube_map.h), each pointing from the emitter toward a viewer. View k is an orthographic
// image of P x P pixels of the emitter's bounding disk: pixel (i, j) (i right, j up) is
// centred at offset b = x right_k + y up_k from the bounding sphere's centre c, with
// x = (2 (i + 0.5) / P - 1) a and y likewise (a the bounding radius), and holds the mean
// radiance of rays travelling along -v_k through its square (RGB, the field's units).
// right_k and up_k are viewAxes(v_k).
//
// A ray (origin o, unit direction d, light frame) passing c at offset b (the vector from c
// to the ray's point nearest c, |b| < a) sees: the views around -d interpolated bilinearly
// on their face's D x D grid (clamped at the face's edges), each at b bilinearly over its
// pixels (clamped at the image's edges).
#pragma once

#include <Imath/ImathVec.h>

#include <cstdint>
#include <vector>

namespace opal {

struct EmitterViews {
    std::uint32_t directionFaceSize = 0;  // D; 0: no views
    std::uint32_t imageSize = 0;          // P
    std::vector<float> radiance;          // view-major, row j, pixel i, RGB

    std::uint32_t views() const { return 6 * directionFaceSize * directionFaceSize; }
    std::uint64_t values() const { return 3ull * views() * imageSize * imageSize; }
    bool empty() const { return directionFaceSize == 0; }
};

// The image axes of the view toward unit `v`: right = normalize(up0 x v) with up0 = +Y, or
// +Z when |v.y| > 0.999; up = v x right.
void viewAxes(const Imath::V3d& v, Imath::V3d& right, Imath::V3d& up);

// The radiance a ray with unit direction `d` passing the centre at offset `b` sees
// (light frame; `radius` the bounding radius). Zero when |b| >= radius or there are no views.
Imath::V3f viewedRadiance(const EmitterViews& views, double radius, const Imath::V3d& d, const Imath::V3d& b);

}  // namespace opal
