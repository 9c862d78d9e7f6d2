// The machine's sustainable memory bandwidth, measured in the same run as the timings it is
// compared with: STREAM's triad a[i] = b[i] + s c[i] (McCalpin), parallel with TBB over arrays
// far larger than the caches, counting 3 x 8 bytes per element as STREAM does (no
// write-allocate traffic). And the bytes each relighting edit must stream at least, so a
// time can be set beside its floor: bytes / bandwidth.
#pragma once

#include "schema/asset/translucent_asset.h"

#include <cstddef>

namespace opal::bench {

// Bytes per second: the median of `repeats` triads over three arrays of `elements` doubles.
double triadBandwidth(std::size_t elements = std::size_t(1) << 24, int repeats = 9);

// The least each case reads and writes once (bytes), from the engine's own layouts:
//   light:       the compact transfer (TransferProduct::memoryBytes), the Haar-transformed
//                moments read and the products y written (samples x K x 3 terms floats);
//                with the harmonic transfer also G read (samples x 3 x Q floats: a light
//                moved again under the same material, RelightEngine::smoothPass) and the
//                harmonic functions read twice (fit and residual: samples x Q floats)
//   environment: the compact dome vectors (EnvironmentVectors::memoryBytes), then as light
//   material:    z_k read (samples x 3 x K floats), radiance written, the vertex gather's
//                weights, indices and order read (VertexGather::memoryBytes) and the
//                vertex radiance written
//   pass:        every AOV channel of every pixel read and written once (the running mean),
//                as float; colorPass the same for color alone (what opal-view binds)
struct StreamedBytes {
    double light = 0.0, environment = 0.0, material = 0.0, pass = 0.0, colorPass = 0.0;
    // The first material edit after a light edit: material, and w1 U read once (samples x Q
    // x K floats) to fold the smooth part into z_k (RelightEngine::smoothPass).
    double materialAfterLight = 0.0;
};

StreamedBytes streamedBytes(const TranslucentAsset& asset, int width, int height);

}  // namespace opal::bench
