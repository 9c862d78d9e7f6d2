// The classic peer of the relighting engine: Jensen and Buhler's hierarchical dipole
// (SIGGRAPH 2002; pbrt-v2's DipoleSubsurfaceIntegrator). The same sum as referenceGather
// (delegate/relight/reference_gather.h),
//
//   L(x_o) = (1/pi) sum_i R_d(|x_o - x_i|) A_i E(x_i),
//
// evaluated over an octree of the samples: each node keeps its total area A, its
// area-weighted mean irradiance E (so that A E is the node's total flux, per channel) and
// its flux-weighted mean position p (weights A_i Y(E_i), Y the luminance). An output x_o uses
// a node's aggregate R_d(|x_o - p|) A E when x_o lies outside the node's cell and the node's
// solid angle A / |x_o - p|^2 is below maxError; otherwise it descends, and leaves sum their
// samples exactly (the output's own sample with the disk self term, as referenceGather).
// maxError = 0 descends everywhere: the exact gather.
//
// The cell structure depends on the positions only and is built once; the aggregates depend
// on E and are refitted per light change (setIrradiance); a material change only evaluates.
#pragma once

#include "schema/asset/translucent_asset.h"

#include <cstdint>
#include <span>
#include <vector>

namespace opal::bench {

class JensenBuhlerOctree {
public:
    // pbrt-v2's leaves: up to 8 samples; cells stop splitting at depth 16 (coincident samples
    // then share one larger leaf).
    static constexpr std::uint32_t kLeafSamples = 8;
    static constexpr std::uint32_t kMaxDepth = 16;
    static constexpr double kDefaultMaxError = 0.05;  // pbrt-v2's default

    // Positions in mm and areas in mm^2 via asset.unitsPerMm. Throws opal::Error for an asset
    // without samples.
    explicit JensenBuhlerOctree(const TranslucentAsset& asset);

    // E(x_i) per sample, samples x 3 (referenceGather's input). Throws opal::Error on a size
    // mismatch.
    void setIrradiance(std::span<const float> irradiance);

    struct Result {
        std::vector<float> radiance;       // outputs x 3
        double interactionsPerOutput = 0;  // dipole evaluations (aggregates + samples) per output
    };
    // L at the outputs (every sample when empty). Throws opal::Error before setIrradiance, for
    // maxError negative or not finite, an invalid material or an output out of range.
    Result radiance(const Material& material, double maxError = kDefaultMaxError,
                    std::span<const std::uint32_t> outputs = {}) const;

    std::size_t nodes() const { return nodes_.size(); }

private:
    struct Node {
        double lo[3], hi[3];                 // the cell (mm)
        std::uint32_t begin = 0, end = 0;    // its samples in order_ (leaves)
        std::uint32_t firstChild = 0;        // children are contiguous in nodes_
        std::uint32_t children = 0;          // 0: a leaf
        double area = 0.0;                   // mm^2
        double position[3] = {0, 0, 0};      // flux-weighted (mm)
        double irradiance[3] = {0, 0, 0};    // area-weighted
    };
    struct Point {
        double position[3];  // mm
        double area;         // mm^2
        double irradiance[3];
        std::uint32_t sample;
    };

    void split(std::uint32_t node, std::uint32_t depth);
    void refit(std::uint32_t node);
    bool inside(const Node& node, const double x[3]) const;

    std::vector<Node> nodes_;    // nodes_[0] is the root
    std::vector<Point> points_;  // in leaf order
    std::vector<std::uint32_t> slot_;  // sample -> its index in points_
    bool lit_ = false;
};

}  // namespace opal::bench
