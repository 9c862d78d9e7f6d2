// A dome light as the pixel loop looks it up (docs/ARCHITECTURE.md#image-formation): the radiance
// toward world directions, for the background behind the meshes and the specular layer's
// reflection, a block of pixels at a time.
//
//   radiance(d) = scale * LatLongMap::sampleLevel(level, latLongCoordinates(d * domeFromWorld))
//
// in float (lat_long_lookup.h's float atan2, the map's bilinear). The AVX2 + FMA kernel
// (chosen at run time, as TransferProduct's) does eight directions at once with gathered
// texels; the portable path does one at a time. They agree to float rounding (tests).
// Measured on the 720p benchmark frame (78% of it background, the rest reflecting the
// dome): 74 -> 57 ms median.
#pragma once

#include "delegate/relight/environment_light.h"

#include <Imath/ImathMatrix.h>
#include <Imath/ImathVec.h>

#include <cstddef>
#include <memory>

namespace opal {

class DomeLookup {
public:
    static constexpr std::size_t kLanes = 8;

    // domeFromWorld: a rotation (row vectors); scale: color * intensity * 2^exposure.
    // simd: use the AVX2 + FMA kernel where the CPU has it (false: always portable).
    DomeLookup(std::shared_ptr<const LatLongMap> map, const Imath::M33d& domeFromWorld, const Imath::V3f& scale,
               bool simd = true);

    bool usesSimd() const { return simd_; }
    // The pyramid level for lookups `footprint` radians wide (LatLongMap::levelFor).
    int levelFor(double footprint) const { return map_->levelFor(footprint); }

    Imath::V3f radiance(const Imath::V3f& direction, int level) const;
    // out[i] = radiance(directions[i], level) for i < count <= kLanes.
    void radiance(const Imath::V3f* directions, std::size_t count, int level, Imath::V3f* out) const;

private:
    std::shared_ptr<const LatLongMap> map_;
    float domeFromWorld_[9];  // row vectors: dome = direction * M, M[row * 3 + column]
    Imath::V3f scale_;
    bool simd_ = false;
};

}  // namespace opal
