// One incident-radiance cube map Haar compressed (schema/wavelet/haar.h, per face, RGB
// interleaved): its coefficients ranked by their RGB squared norm r^2 + g^2 + b^2, the
// largest kept until they hold at least `keptEnergy` of the map's energy (ties by
// position, so the choice is deterministic). The transform is orthonormal, so the map's
// relative L2 error (over texels) is sqrt(dropped / energy) <= sqrt(1 - keptEnergy).
#pragma once

#include "schema/asset/cube_map.h"

#include <cstdint>
#include <vector>

namespace opal {

struct CompressedCubeMap {
    std::vector<std::uint32_t> indices;  // ascending
    std::vector<float> values;           // 3 per index
    double energy = 0.0;                 // sum of squares of every coefficient (= of every texel value)
    double droppedEnergy = 0.0;          // of the coefficients left out
};

// `rgb`: 3 floats per texel; transformed in place.
CompressedCubeMap compressCubeMap(std::vector<float>& rgb, const CubeMapLayout& layout, double keptEnergy);

}  // namespace opal
