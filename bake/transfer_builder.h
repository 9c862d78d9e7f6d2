// Step 6 of the bake (docs/ARCHITECTURE.md#transfer and #compression; the paper's "Precomputing and
// Compression of Scatter Transmission"): the scattering transfer T_k[o][i] = b_k(|x_o - x_i|) A_i
// for all basis functions k, computed row by row and compressed in two steps without ever holding
// the dense N x N matrix:
//   step 1 (light dimension, w0): each row of T_k, laid out on the chart grid, is Haar
//          transformed and its `keepFraction` most important coefficients kept, ranked
//          by |c_j| area_j^0.75, area_j the cells basis function j covers
//          (transfer_builder.cpp);
//   step 2 (spatial dimension, w1): every column of the retained matrix is transformed
//          along the output dimension with CDF 9/7, and the coefficients of all K
//          matrices that carry `energyFraction` of their weighted energy are kept
//          (weighted by what a coefficient contributes to L = sum_k s_k T_k E:
//          transfer_builder.cpp); the transfer's relative error is about
//          sqrt(1 - energyFraction).
// The diagonal is left out (T_k[o][o] = 0, SelfTerm::AtRunTime): a sample gathers its own
// light over its own area, a disk, and the relighter adds that with the current material's
// exact dipole (schema/asset/self_term.h). Through the basis it was the largest error at the
// short end of the editable range (docs/ARCHITECTURE.md#self-term), and its spike on every
// row's diagonal is what the spatial 9/7 step compresses worst.
// The result is ^{w1}T_k^{w0^-1}, one sparse matrix per k (rows: 9/7 coefficients of the
// output, columns: Haar coefficients of the light).
#pragma once

#include "bake/progress.h"
#include "schema/asset/translucent_asset.h"

#include <cstdint>
#include <span>
#include <vector>

namespace opal {

struct TransferSettings {
    double keepFraction = 0.01;    // step 1: fraction of each row's Haar coefficients kept
    // step 2: fraction of the weighted 9/7 energy kept. Not the paper's 95-98%: the
    // relative error is about sqrt(1 - energyFraction), so 0.97 leaves ~17% (measured
    // 20% on a 16,384-sample candle) and 0.99995 ~0.7% (0.67% on the 65,536-sample bunny).
    // 0.99998 because the image targets ask for more than the transfer's mean error: on the
    // 4,096-sample bunny (opal-bench accuracy, default material) 0.99995 / 0.99998 / 0.99999
    // gave a per-pixel luminance error 95th percentile of 3.2 / 2.2 / 1.7% (distant light;
    // target 3%), chromaticity 0.0031 / 0.0022 / 0.0018, for sidecars of 10.0 / 12.7 /
    // 15.1 MB (candle 5.8 / 7.6 / 9.4 MB).
    double energyFraction = 0.99998;
    // step 1: but at least this many per row on average over k (all N when N is smaller).
    // A fraction alone starves small bakes: 1% of 1,024 samples is 10 per row, and the
    // 1,024-sample candle's image was then 1.8% off its exact reference (luminance 95th
    // percentile 16%). What a row needs is set by the scattering profile's footprint on the
    // charts more than by N. Measured on the candle's image against the exact reference
    // (point light, energy 0.99995), luminance error 95th percentile at 64 / 128 / 256 /
    // 512 per row: 1,024 samples 2.4 / 1.5 / 2.0 / 2.0%, 4,096 samples 2.7 / 2.3 / 1.8 /
    // 1.9% (chromaticity 0.0050 / 0.0035 / 0.0039 / 0.0040 and 0.0065 / 0.0051 / 0.0042 /
    // 0.0045): beyond 256 step 2 bounds the error. 16,384 samples keep 256 (1% is 164);
    // from 25,600 samples up the fraction governs.
    std::uint32_t minPerRow = 256;
};

struct TransferStats {
    std::uint64_t rawBytes = 0;    // N x N x K float32
    std::uint64_t step1Bytes = 0;  // retained entries after step 1 (index + value)
    std::uint64_t step2Bytes = 0;  // retained entries after step 2 (index + value)
    std::uint64_t step2NonZeros = 0;
    double energyKept = 1.0;       // step 2 weighted energy kept, over all k
    double step1PerRow = 0.0;      // Haar coefficients kept per row, averaged over k
    bool step1Floor = false;       // the count is the minPerRow floor, not keepFraction x N
};

// samples are in grid order (layout.cells() of them), positions in scene units.
CompressedTransfer buildTransfer(std::span<const SurfaceSample> samples, const ChartLayout& layout,
                                 double unitsPerMm, const ProfileBasis& basis,
                                 const TransferSettings& settings, ProgressSink* progress,
                                 const CancelToken& cancel, TransferStats* stats);

}  // namespace opal
