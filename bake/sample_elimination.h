// Weighted sample elimination (Yuksel 2015, "Sample Elimination for Generating Poisson
// Disk Sample Sets"): from a larger set of random candidates on a surface, remove the most
// crowded one until `count` remain. The result has blue-noise spacing (no two samples much
// closer than the Poisson-disk radius) and keeps the candidates' density, i.e. uniform
// by area when the candidates are. Distances are Euclidean; candidates whose normals
// disagree by more than 120 degrees do not crowd each other, so the two sides of a thin
// part are sampled as separate surfaces.
#pragma once

#include <Imath/ImathVec.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace opal {

// Returns the indices of the `count` kept candidates, in increasing order. `surfaceArea`
// sets the Poisson-disk radius r_max = sqrt(area / (2 sqrt(3) count)) (hexagonal packing).
// Deterministic: ties are broken by index and all parallel work is order-independent.
std::vector<std::uint32_t> eliminateSamples(std::span<const Imath::V3f> positions,
                                            std::span<const Imath::V3f> normals, std::size_t count,
                                            double surfaceArea);

// The Poisson-disk radius of `count` samples on `surfaceArea` (see above).
double poissonDiskRadius(double surfaceArea, std::size_t count);

}  // namespace opal
