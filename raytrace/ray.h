// A ray segment origin + t direction, t in [tNear, tFar], that Embree can always trace.
//
// Debian's Embree 3 keeps its assertions: a ray whose origin or direction has a NaN or a
// coordinate above about 1.8e18 (FLT_LARGE), or whose tnear / tfar is NaN, or whose tnear
// is negative, aborts the process inside the intersector instead of reporting an error.
// Every ray Opal traces (camera, shadow, occlusion, the bake's visibility) is a Ray, and a
// Ray is valid by construction: the constructor checks its inputs and turns anything Embree
// would reject into the empty segment, on which Embree finds nothing (no hit, not occluded).
// Callers that must know (a shading point that came out non-finite) ask empty().
#pragma once

#include <Imath/ImathVec.h>

#include <cmath>
#include <limits>

namespace opal {

class Ray {
public:
    // Origin and direction coordinates must stay below this magnitude (Embree's FLT_LARGE
    // is 1.844e18; the margin keeps origin + t direction arithmetic inside it).
    static constexpr float kMaxCoordinate = 1e18f;

    // The empty segment.
    Ray() = default;
    // origin + t direction for t in [tNear, tFar]; tFar may be +infinity. Inputs Embree
    // would reject (non-finite or out-of-range origin or direction, a zero direction, a NaN
    // or negative tNear, a NaN tFar, tNear > tFar) give the empty segment.
    Ray(const Imath::V3f& origin, const Imath::V3f& direction, float tNear, float tFar) {
        if (traceable(origin, direction, tNear, tFar)) {
            origin_ = origin;
            direction_ = direction;
            tNear_ = tNear;
            tFar_ = tFar;
        }
    }

    const Imath::V3f& origin() const { return origin_; }
    const Imath::V3f& direction() const { return direction_; }
    float tNear() const { return tNear_; }
    float tFar() const { return tFar_; }
    // True for the empty segment: nothing can be hit on it.
    bool empty() const { return tNear_ > tFar_; }

    static bool traceable(const Imath::V3f& origin, const Imath::V3f& direction, float tNear, float tFar) {
        return inRange(origin) && inRange(direction) && direction != Imath::V3f(0.0f) && tNear >= 0.0f &&
               tNear <= tFar;  // false for a NaN tNear or tFar; tFar may be +inf
    }

private:
    // |c| <= kMaxCoordinate for each coordinate: false for NaN and infinities.
    static bool inRange(const Imath::V3f& v) {
        return std::abs(v.x) <= kMaxCoordinate && std::abs(v.y) <= kMaxCoordinate && std::abs(v.z) <= kMaxCoordinate;
    }

    // The empty segment: a finite origin and direction Embree accepts, and tNear > tFar.
    Imath::V3f origin_{0.0f};
    Imath::V3f direction_{0.0f, 0.0f, 1.0f};
    float tNear_ = 1.0f;
    float tFar_ = 0.0f;
};

}  // namespace opal
