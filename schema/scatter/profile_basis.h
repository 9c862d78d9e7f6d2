// The PCA profile basis (docs/ARCHITECTURE.md#pca; the paper's section "Diffuse Scattering
// Material Function Decomposition" and its equation (5)): R_d(r, sigma) ~= sum_k s_k(sigma) b_k(r).
#pragma once

#include "schema/scatter/material.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace opal {

struct ProfileBasisSettings {
    int K = 12;                      // number of basis functions kept
    // mm; 0 picks 400 z_min with z_min = 1/(sigmaSPrimeMax + sigmaAMax) the depth of the
    // range's narrowest profile (36 mm for the default range). The K-term error grows with
    // rMax / z_min (see profile_basis.cpp); bakes pass the asset's size.
    double rMax = 0.0;
    int radialSamples = 0;           // 0 picks the default (256, see radial_grid.h)
    int trainingMaterials = 0;       // 0 picks the default (2048 channels, material_sampler.h)
    EditableRange range = EditableRange::coveringPresets();
    std::uint64_t seed = 1;
};

class ProfileBasis {
public:
    ProfileBasis() = default;
    // Rebuilds a basis from stored samples (as read from an asset).
    // values is K x radii.size(), row-major. Throws opal::Error on inconsistent sizes.
    ProfileBasis(std::vector<double> radii, std::vector<double> weights, std::vector<double> values,
                 std::vector<double> eigenvalues, EditableRange range);

    // Weighted PCA (Eigen SVD) over materials sampled log-uniformly in settings.range.
    // Deterministic for given settings. Throws opal::Error naming the bad setting, or
    // saying how many components the training profiles have when rMax is too short for
    // K of them (a few times z_min or less).
    static ProfileBasis fit(const ProfileBasisSettings& settings);

    int K() const { return static_cast<int>(eigenvalues_.size()); }
    double rMax() const;
    std::span<const double> radii() const { return radii_; }      // r_l, mm
    std::span<const double> weights() const { return weights_; }  // w_l = 2 pi r_l dr_l
    std::span<const double> values() const { return values_; }    // b_k(r_l), K x L
    // singular values^2 / J (J training materials): since every row of M has unit norm,
    // the fraction of the training energy each b_k carries; decreasing, sum <= 1.
    std::span<const double> eigenvalues() const { return eigenvalues_; }
    const EditableRange& range() const { return range_; }

    // b_k(r), linearly interpolated between the stored samples; 0 beyond rMax. Throws for
    // k outside [0, K) or r negative or NaN.
    double evaluate(int k, double r) const;
    // out[k] = integral_0^radius b_k(r) 2 pi r dr for every k (out: K values), exact for the
    // piecewise-linear b_k of evaluate(); the disk is cut at rMax. The transfer's self term
    // (docs/ARCHITECTURE.md#total-reflectance): sum_k s_k out[k] ~= dipoleDiskReflectance(radius).
    // Throws opal::Error for a negative or NaN radius.
    void diskIntegrals(double radius, std::span<double> out) const;
    // s_k(sigma): K numbers per channel, the projection s0_k = sum_l w_l R_d(r_l, sigma) b_k(r_l)
    // moved to the nearest coefficients whose profile sum_k s_k b_k(r) is nonnegative at
    // every r (docs/ARCHITECTURE.md#pca). Throws opal::Error for non-positive or non-finite
    // coefficients or eta outside [1, 3].
    std::vector<double> coefficients(const DipoleCoefficients& c) const;
    // s0 alone (the profile may dip below 0 in its far tail).
    std::vector<double> unconstrainedCoefficients(const DipoleCoefficients& c) const;
    // The nearest coefficients to s (K of them) whose profile is nonnegative at every r and
    // has the same total reflectance: what coefficients() does to s0. Throws opal::Error
    // when s.size() != K.
    std::vector<double> nonnegative(std::vector<double> s) const;
    std::array<std::vector<double>, 3> project(const Material& m) const;
    // sum_k s_k b_k(r).
    double reconstruct(std::span<const double> s, double r) const;
    // Area-weighted relative L2 error of the K-term reconstruction of R_d(., c) over
    // [0, rMax]: sqrt(sum_l w_l (R - R~)^2 / sum_l w_l R^2).
    double relativeError(const DipoleCoefficients& c, int K = -1) const;

private:
    // What coefficients()' nonnegative projection needs of the basis alone, made once by the
    // constructor (it would otherwise be most of a material edit's projection time): an
    // orthonormal basis N of the complement of d (K x (K - 1)), and for each node l that
    // constrains anything, g_l = N^T b(r_l) scaled to unit length and |g_l|.
    struct NonnegativeFrame {
        std::vector<double> complement;  // N, K x (K - 1), column-major
        std::vector<double> normals;     // g_l / |g_l|, (K - 1) x nodes, column-major
        std::vector<double> norms;       // |g_l|
        std::vector<std::size_t> nodes;  // l
    };
    void prepareNonnegativeFrame();

    std::vector<double> radii_, weights_, values_, eigenvalues_;
    EditableRange range_;
    NonnegativeFrame frame_;
};

// Fast evaluation of all K basis functions at once, for the bake's N^2 inner loop:
// a dense table in u = sqrt(r / rMax) with linear interpolation.
class BasisLookup {
public:
    // Throws opal::Error for an empty basis or resolution < 1.
    BasisLookup(const ProfileBasis& basis, int resolution = 4096);
    int K() const { return K_; }
    float rMax() const { return rMax_; }  // mm
    // out[k] = b_k(r) for k < K; r in mm. Zero beyond rMax (and for r < 0 or NaN).
    // No allocation, one branch: the bake calls it for every pair of samples.
    void evaluate(float r, float* out) const;
    // rows[k * stride + j] = b_k(r[j]) * weight[j] for k < K, j < r.size(): evaluate()
    // followed by the product, bit for bit, with the table position found once per radius
    // and four k interpolated at a time. Requires weight.size() >= r.size() and stride >=
    // r.size() (unchecked: this is the bake's inner loop).
    void evaluateWeighted(std::span<const float> r, std::span<const float> weight, float* rows,
                          std::size_t stride) const;

private:
    int K_ = 0;
    int width_ = 0;             // K rounded up to a multiple of 4 (zero padded)
    int resolution_ = 0;
    float rMax_ = 0.0f;
    float scale_ = 0.0f;        // resolution / sqrt(rMax): r -> table position
    // (resolution + 1) rows of 2 x width_: interval i's start values b_k(u_i) and steps
    // b_k(u_{i+1}) - b_k(u_i); the last row is zeros (where r is outside the table).
    std::vector<float> table_;
};

}  // namespace opal
