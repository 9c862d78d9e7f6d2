// One row of the scattering transfer for every basis function (docs/ARCHITECTURE.md#transfer):
// T_k[o][i] = b_k(|x_o - x_i|) A_i. Step 1 of the transfer evaluates N such rows of N, so
// this is the bake's innermost loop: positions are kept as separate x, y, z arrays (the
// distance loop vectorizes) and the basis table position is found once per pair for all K.
#pragma once

#include "schema/asset/normal_harmonics.h"
#include "schema/asset/translucent_asset.h"
#include "schema/scatter/profile_basis.h"

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace opal {

// Sample positions in mm and areas in mm^2: the basis is tabulated in mm
// (docs/ARCHITECTURE.md#units).
struct TransferSamples {
    std::vector<float> x, y, z;  // mm
    std::vector<float> area;     // mm^2
    // f_q(x_i, n_i) of the harmonic set, one plane per q < harmonicSet.count
    // (schema/asset/normal_harmonics.h).
    HarmonicSet harmonicSet;
    std::vector<std::vector<float>> harmonics;

    std::size_t size() const { return area.size(); }
};

// position / unitsPerMm and area / unitsPerMm^2, rounded to float as position * (1 /
// unitsPerMm) and (area * (1 / unitsPerMm)) * (1 / unitsPerMm); the harmonic planes of
// harmonicSetFor(samples), in scene units. Throws opal::Error unless unitsPerMm is
// positive and finite.
TransferSamples toTransferSamples(std::span<const SurfaceSample> samples, double unitsPerMm);

// rows[k * stride + i] = b_k(|x_o - x_i|) A_i for k < lookup.K() and i < N =
// samples.size(), bit for bit the per-pair evaluation (Imath's V3f::length,
// BasisLookup::evaluate, times A_i); the gaps between rows are left alone. Throws
// opal::Error when o >= N, stride < N or rows.size() != (K - 1) * stride + N.
void transferRow(std::size_t o, const TransferSamples& samples, const BasisLookup& lookup,
                 std::span<float> rows, std::size_t stride);

// The same with stride N: rows[k * N + i], rows.size() == K * N.
void transferRow(std::size_t o, const TransferSamples& samples, const BasisLookup& lookup,
                 std::span<float> rows);

// h[k * Q + q] = sum_i rows[k * stride + i] f_q(x_i, n_i), k < K, q < Q =
// samples.harmonicSet.count: a row's transfer of the harmonic set
// (CompressedTransfer::harmonics), summed in float over blocks that fit the cache and in
// double across them. Throws opal::Error for mismatched sizes.
void harmonicRow(std::span<const float> rows, std::size_t stride, std::size_t K, const TransferSamples& samples,
                 std::span<float> h);

// A row stride to use instead of N: N rounded up to whole 64-byte cache lines, plus one.
// All K rows are written at once; with a stride that is a multiple of 4 KiB (N = 65,536
// and every other bake size) they all map to the same cache set, which thrashes the L1
// and L2 caches (measured: 1.5x slower per row at N = 65,536; opal-bench transfer-row).
std::size_t transferRowStride(std::size_t n);

}  // namespace opal
