// The in-memory form of a baked translucent asset: everything the render delegate needs
// to relight it. Lengths are in the asset's scene units; `unitsPerMm` converts them to the
// millimetres that material coefficients (mm^-1) and the profile basis (mm) use.
#pragma once

#include "schema/scatter/fresnel_moments.h"
#include "schema/scatter/material.h"
#include "schema/scatter/profile_basis.h"
#include "schema/wavelet/chart_layout.h"
#include "schema/wavelet/sparse.h"

#include <Imath/ImathVec.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace opal {

// The subdivided (limit-surface) mesh that is rendered. Right-handed, counter-clockwise
// winding seen from outside, normals point outward.
struct RenderMesh {
    std::vector<Imath::V3f> points;
    std::vector<Imath::V3f> normals;  // per vertex, unit
    std::vector<std::int32_t> faceVertexCounts;
    std::vector<std::int32_t> faceVertexIndices;
};

// One surface sample x_i with its normal and the surface area it stands for.
struct SurfaceSample {
    Imath::V3f position;
    Imath::V3f normal;
    float area = 0.0f;  // scene units^2
};

// Per render-mesh vertex, weights onto nearby samples (CSR: vertex v uses entries
// offsets[v] .. offsets[v+1]); the weights of one vertex sum to 1 (the sidecar accepts
// 1 +- 1e-3), so every vertex has at least one entry.
struct VertexWeights {
    std::vector<std::uint32_t> offsets;  // vertices + 1
    std::vector<std::uint32_t> samples;
    std::vector<float> weights;
};

// The two-step compressed transfer (docs/ARCHITECTURE.md#compression): one matrix per basis
// function k, ^{w1}T_k^{w0^-1}. Rows are CDF 9/7 coefficients of the output (spatial) dimension,
// columns Haar coefficients of the light dimension, both in the chart layout: every matrix is
// samples x samples, with strictly ascending columns within each row.
//
// Where the diagonal T_k[o][o] (a sample's own light, gathered over its own disk) lives
// (docs/ARCHITECTURE.md#self-term): in the matrices, as the basis' disk integrals
// (sidecars before 2.3), or left out of them (T_k[o][o] = 0) and added at run time with
// the current material's exact dipole disk reflectance (self_term.h).
enum class SelfTerm : std::uint32_t { InTransfer = 0, AtRunTime = 1 };

// The functions whose exact transfer CompressedTransfer::harmonics holds
// (schema/asset/normal_harmonics.h, docs/ARCHITECTURE.md#harmonic-transfer): the nine
// normal harmonics Y_q(n) (count 9, sidecars 2.5), or those times each of (1, x', y', z'),
// x' = (x - centre) inverseScale the sample position in the set's frame (count 36, from
// 2.6). The frame only conditions the fit: the 36 span the same space in any frame.
struct HarmonicSet {
    std::uint32_t count = 36;
    Imath::V3f centre{0.0f, 0.0f, 0.0f};  // scene units
    float inverseScale = 1.0f;            // 1 / scene units
};

struct CompressedTransfer {
    std::vector<SparseMatrix> perBasis;  // K
    // Per matrix, the step of the grid its values are stored on (transfer_value_grid.h);
    // 0: stored exactly. Empty means all 0.
    std::vector<double> valueSteps;
    double keepFraction = 0.01;          // step 1
    double energyFraction = 0.99998;     // step 2
    SelfTerm selfTerm = SelfTerm::InTransfer;
    // T_k f_q, lossless (schema/asset/normal_harmonics.h): harmonics[(o * K + k) * Q + q] =
    // sum_{i != o} T_k[o][i] f_q(x_i, n_i), one per output o (grid order), basis function k
    // and function q < Q = harmonicSet.count. Empty: not baked (sidecars before 2.5); the
    // matrices then carry all of the light.
    std::vector<float> harmonics;
    HarmonicSet harmonicSet;  // what `harmonics` is the transfer of

    double valueStep(std::size_t k) const { return k < valueSteps.size() ? valueSteps[k] : 0.0; }
};

// What an environment vector holds (docs/ARCHITECTURE.md#dome-light): the visible
// transport V cos P_m dOmega itself (sidecars before 2.4), or its occluded residual
// (1 - V) cos P_m dOmega, which the delegate subtracts from the unoccluded integral.
enum class EnvironmentVectorKind : std::uint32_t { Visible = 0, Occluded = 1 };

// Environment light transfer (Ng et al. 2003): per sample, (occluded) visibility x cosine
// over a 6 x size x size cube map, Haar transformed, the largest terms kept. F_t(eta, .) is
// applied at run time through `fresnelTerms` moments: vector m holds V cos(theta)
// P_m(cos(theta)) dOmega, or (1 - V) cos(theta) P_m(cos(theta)) dOmega (`kind`).
struct EnvironmentTransfer {
    std::uint32_t cubeFaceSize = 32;
    std::uint32_t fresnelTerms = 1;
    // The P_m of the vectors (schema/scatter/fresnel_moments.h); Legendre for sidecars
    // without chunk FBAS (written before 2.2).
    FresnelBasis fresnelBasis = FresnelBasis::Legendre;
    EnvironmentVectorKind kind = EnvironmentVectorKind::Visible;
    // CSR over (sample * fresnelTerms + m); empty offsets mean "not baked".
    std::vector<std::uint32_t> offsets;
    std::vector<std::uint32_t> indices;  // cube-map Haar coefficient index, ascending per row
    std::vector<float> values;
};

struct BakeSettings {
    std::string source;            // input mesh path as given
    std::string scheme;            // "catmullClark" or "loop"
    std::uint32_t level = 0;       // uniform subdivision level
    std::uint64_t seed = 1;
    std::uint32_t envTerms = 1024;  // the most environment terms one sample keeps
    double envError = 0.005;        // per sample: what the dropped terms may hold (bake/environment_visibility.h)
    // The bake's identifier (bake_id.h), recorded in the layer and the sidecar; empty for
    // assets baked before Opal recorded one (and for assets made in memory).
    std::optional<std::uint64_t> identifier;
};

// Where each part lives on disk: name.usda holds name, unitsPerMm, mesh, basis,
// defaultMaterial, range and bake; the sidecar name.<bake id>.opal (sidecar.h) holds
// layout, samples, vertexWeights, transfer and environment.
struct TranslucentAsset {
    std::string name;
    double unitsPerMm = 1.0;
    RenderMesh mesh;
    ChartLayout layout;
    std::vector<SurfaceSample> samples;  // layout.cells() of them, in grid order
    VertexWeights vertexWeights;
    ProfileBasis basis;
    CompressedTransfer transfer;
    EnvironmentTransfer environment;
    Material defaultMaterial;
    EditableRange range;
    BakeSettings bake;
};

}  // namespace opal
