// Deterministic random single-channel materials inside an editable range: the training
// set of the PCA profile basis (docs/ARCHITECTURE.md#pca) and held-out sets that measure it.
#pragma once

#include "schema/scatter/dipole.h"
#include "schema/scatter/material.h"

#include <cstdint>
#include <vector>

namespace opal {

// count channels with sigma_s' and sigma_a log-uniform and eta uniform in range, drawn
// independently. The same (range, count, seed) gives the same materials on every platform
// (std::mt19937_64 with an explicit mapping to [0, 1)). Throws opal::Error for an invalid
// range or a negative count.
std::vector<DipoleCoefficients> sampleChannels(const EditableRange& range, int count, std::uint64_t seed);

}  // namespace opal
