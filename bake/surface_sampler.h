// Uniform, blue-noise surface samples x_i on the render mesh (docs/ARCHITECTURE.md#wavelet-domain):
// the points where irradiance is gathered and scattered light is computed.
//
// Method: `candidatesPerSample` x N random candidates, area-weighted and stratified over
// the triangles (candidate j takes the quantile (j + u_j) / C of the cumulative area), then
// weighted sample elimination down to exactly N. Each sample lies on a render-mesh triangle;
// its normal is the barycentric interpolation of the limit normals, normalized.
//
// Areas: every sample gets total area / N. After elimination the samples are evenly spaced,
// so each one's share of the surface (its Voronoi cell) is close to the mean; equal areas
// sum exactly to the surface area and carry no estimator noise into the transfer.
#pragma once

#include "schema/asset/translucent_asset.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace opal {

// Where a sample came from: a render-mesh face and barycentric weights on three of its
// vertices (the fan triangle it was drawn from).
struct SampleOrigin {
    std::uint32_t face = 0;
    std::array<std::uint32_t, 3> vertices{};
    Imath::V3f barycentric{0.0f};  // sums to 1
};

struct SurfaceSampling {
    std::vector<SurfaceSample> samples;
    std::vector<SampleOrigin> origins;  // parallel to samples
    double surfaceArea = 0.0;           // of the render mesh
};

struct SamplingOptions {
    std::uint64_t seed = 1;
    std::uint32_t candidatesPerSample = 4;  // more gave no wider spacing in our tests
};

// `count` samples over `mesh` (which must have one unit normal per point). Same mesh,
// count and seed give the same samples, whatever the thread count. Throws opal::Error for
// a mesh without area or without normals, or count == 0.
SurfaceSampling sampleSurface(const RenderMesh& mesh, std::size_t count, const SamplingOptions& options = {});

// Puts the samples in a new order: sample i of the result is sample order[i] of the input
// (e.g. the chart parameterization's grid order). `order` must be a permutation.
void reorderSamples(SurfaceSampling& sampling, std::span<const std::uint32_t> order);

}  // namespace opal
