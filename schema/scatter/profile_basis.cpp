#include "schema/scatter/profile_basis.h"

#include "schema/error.h"
#include "schema/scatter/material_sampler.h"
#include "schema/scatter/nonnegative_least_squares.h"
#include "schema/scatter/radial_grid.h"

#include <Eigen/Dense>
#include <Eigen/SVD>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <sstream>
#include <string>

namespace opal {

namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// What fit() does when a setting is 0.
//
// The basis must represent profiles whose scale runs from the narrowest material's depth
// z_min = 1/(sigma_s'max + sigma_a max) up to rMax, and its K-term error is set by the
// ratio rMax / z_min: more radial samples or training materials do not lower it (both
// are converged at the defaults). Over 1,000 held-out materials of the default range
// (z_min = 0.09 mm), K = 12 gives a mean relative L2 error of 8.7e-4 at the default
// rMax = 400 z_min = 36 mm, 1.7e-3 at rMax = 100 mm (K = 16: 1.8e-4). At 36 mm every
// preset channel keeps at least 97% of its total diffuse reflectance inside rMax (chicken
// red 97.2%, skimmilk red 98.2%, the others over 98.9%). Bakes pass the asset's size.
constexpr double kDefaultScaleRatio = 400.0;
constexpr int kDefaultRadialSamples = 256;
constexpr int kDefaultTrainingMaterials = 2048;
// The grid's linear core r0 is this fraction of z_min (the grid is geometric beyond r0).
constexpr double kCoreFraction = 0.5;

struct FitPlan {
    int K = 0;
    double zMin = 0.0;  // the depth 1/sigma_t' of the range's narrowest profile, mm
    double rMax = 0.0;
    double r0 = 0.0;
    int radialSamples = 0;
    int trainingMaterials = 0;
};

FitPlan planFit(const ProfileBasisSettings& s) {
    s.range.validate("ProfileBasis::fit settings.range");
    FitPlan plan;
    plan.K = s.K;
    const double zMin = 1.0 / (s.range.sigmaSPrimeMax + s.range.sigmaAMax);
    plan.zMin = zMin;
    plan.rMax = s.rMax == 0.0 ? kDefaultScaleRatio * zMin : s.rMax;
    plan.radialSamples = s.radialSamples == 0 ? kDefaultRadialSamples : s.radialSamples;
    plan.trainingMaterials = s.trainingMaterials == 0 ? kDefaultTrainingMaterials : s.trainingMaterials;
    plan.r0 = kCoreFraction * zMin;
    if (!std::isfinite(plan.rMax) || !(plan.rMax > 0.0))
        throw Error("ProfileBasis::fit: settings.rMax = " + std::to_string(s.rMax) +
                    " mm must be positive and finite (or 0 for the default)");
    if (plan.radialSamples < 2)
        throw Error("ProfileBasis::fit: settings.radialSamples = " + std::to_string(s.radialSamples) +
                    " must be at least 2 (or 0 for the default)");
    if (plan.trainingMaterials < 1)
        throw Error("ProfileBasis::fit: settings.trainingMaterials = " + std::to_string(s.trainingMaterials) +
                    " must be at least 1 (or 0 for the default)");
    if (plan.K < 1 || plan.K > std::min(plan.radialSamples, plan.trainingMaterials))
        throw Error("ProfileBasis::fit: settings.K = " + std::to_string(s.K) +
                    " must lie in [1, min(radialSamples, trainingMaterials)] = [1, " +
                    std::to_string(std::min(plan.radialSamples, plan.trainingMaterials)) + "]");
    return plan;
}

// Over a radius range much shorter than the profiles' own scale every training profile is
// nearly flat, the training matrix has fewer than K independent rows, and b_k = U_k^T P / S_k
// divides by a zero singular value. Named here instead of surfacing as a NaN basis value.
[[noreturn]] void throwTooFewComponents(const FitPlan& plan, int fitted) {
    std::ostringstream out;
    out << "ProfileBasis::fit: the training profiles over [0, " << plan.rMax << " mm] have only " << fitted
        << " independent components, fewer than K = " << plan.K << ": rMax is " << plan.rMax / plan.zMin
        << " times the narrowest profile's depth z_min = " << plan.zMin
        << " mm, too short a range for the profiles to differ; a larger rMax (is the object's size in "
           "millimetres right?) or a smaller K fits";
    throw Error(out.str());
}

// Row j: R_d(r_l, sigma_j) / ||R_d(., sigma_j)||_w, the per-row normalized training profile.
RowMatrix normalizedProfiles(const RadialGrid& grid, const std::vector<DipoleCoefficients>& training) {
    const Eigen::Index L = static_cast<Eigen::Index>(grid.radii.size());
    const Eigen::Map<const Eigen::VectorXd> w(grid.weights.data(), L);
    RowMatrix profiles(static_cast<Eigen::Index>(training.size()), L);
    tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, profiles.rows()), [&](const auto& rows) {
        for (Eigen::Index j = rows.begin(); j != rows.end(); ++j) {
            for (Eigen::Index l = 0; l < L; ++l) profiles(j, l) = dipoleProfile(grid.radii[l], training[j]);
            profiles.row(j) /= std::sqrt((profiles.row(j).array().square() * w.transpose().array()).sum());
        }
    });
    return profiles;
}

void requireFiniteNonNegative(const std::vector<double>& v, const char* name, bool positive = false) {
    for (std::size_t i = 0; i < v.size(); ++i)
        if (!std::isfinite(v[i]) || v[i] < 0.0 || (positive && v[i] == 0.0))
            throw Error(std::string("ProfileBasis: ") + name + "[" + std::to_string(i) + "] = " +
                        std::to_string(v[i]) + " must be finite and " + (positive ? "positive" : "non-negative"));
}

}  // namespace

ProfileBasis::ProfileBasis(std::vector<double> radii, std::vector<double> weights, std::vector<double> values,
                           std::vector<double> eigenvalues, EditableRange range)
    : radii_(std::move(radii)),
      weights_(std::move(weights)),
      values_(std::move(values)),
      eigenvalues_(std::move(eigenvalues)),
      range_(range) {
    const std::size_t L = radii_.size(), K = eigenvalues_.size();
    std::ostringstream sizes;
    sizes << "ProfileBasis: inconsistent sizes: " << L << " radii, " << weights_.size() << " weights, " << K
          << " eigenvalues and " << values_.size() << " values (expected eigenvalues x radii = " << K * L
          << ", at least 2 radii and 1 eigenvalue)";
    if (L < 2 || K < 1 || weights_.size() != L || values_.size() != K * L) throw Error(sizes.str());
    requireFiniteNonNegative(radii_, "radii");
    requireFiniteNonNegative(weights_, "weights");
    requireFiniteNonNegative(eigenvalues_, "eigenvalues");
    for (std::size_t l = 1; l < L; ++l)
        if (!(radii_[l] > radii_[l - 1]))
            throw Error("ProfileBasis: radii must increase strictly, but radii[" + std::to_string(l) +
                        "] = " + std::to_string(radii_[l]) + " follows " + std::to_string(radii_[l - 1]));
    for (std::size_t i = 0; i < values_.size(); ++i)
        if (!std::isfinite(values_[i]))
            throw Error("ProfileBasis: values[" + std::to_string(i) + "] is not finite");
    range_.validate("ProfileBasis range");
    prepareNonnegativeFrame();
}

// docs/ARCHITECTURE.md#pca, nonnegative profiles: the basis-only part of coefficients().
void ProfileBasis::prepareNonnegativeFrame() {
    const Eigen::Index L = static_cast<Eigen::Index>(radii_.size()), K = this->K();
    if (K < 2) return;
    const Eigen::Map<const RowMatrix> Bt(values_.data(), K, L);  // row k: b_k(r_l)
    Eigen::VectorXd d(K);
    diskIntegrals(rMax(), std::span<double>(d.data(), std::size_t(K)));
    const Eigen::MatrixXd Q = d.householderQr().householderQ();
    const Eigen::MatrixXd N = Q.rightCols(K - 1);  // orthonormal, N^T d = 0
    frame_.complement.assign(N.data(), N.data() + N.size());
    for (Eigen::Index l = 0; l < L; ++l) {
        const Eigen::VectorXd g = N.transpose() * Bt.col(l);
        const double norm = g.norm();
        if (norm == 0.0) continue;  // b(r_l) along d (or zero): nothing to move
        for (Eigen::Index k = 0; k < K - 1; ++k) frame_.normals.push_back(g[k] / norm);
        frame_.norms.push_back(norm);
        frame_.nodes.push_back(std::size_t(l));
    }
}

// docs/ARCHITECTURE.md#pca: M[j][l] = sqrt(w_l) R_d(r_l, sigma_j) / ||R_d(., sigma_j)||_w
// = U S V^T, b_k = V_k / sqrt(w). Since V_k = M^T U_k / S_k, b_k(r_l) = sum_j U_jk P_jl / S_k
// with P the normalized profiles: the same numbers, and also defined at r = 0 where w = 0.
ProfileBasis ProfileBasis::fit(const ProfileBasisSettings& settings) {
    const FitPlan plan = planFit(settings);
    RadialGrid grid = makeRadialGrid(plan.rMax, plan.r0, plan.radialSamples);
    const RowMatrix profiles =
        normalizedProfiles(grid, sampleChannels(settings.range, plan.trainingMaterials, settings.seed));
    const Eigen::Map<const Eigen::VectorXd> w(grid.weights.data(), plan.radialSamples);
    const RowMatrix m = profiles * w.cwiseSqrt().asDiagonal();
    const Eigen::BDCSVD<Eigen::MatrixXd> svd(m, Eigen::ComputeThinU);

    const Eigen::VectorXd singular = svd.singularValues().head(plan.K);
    RowMatrix basis = svd.matrixU().leftCols(plan.K).transpose() * profiles;
    std::vector<double> eigenvalues(plan.K);
    for (int k = 0; k < plan.K; ++k) {
        Eigen::Index peak = 0;
        basis.row(k).cwiseAbs().maxCoeff(&peak);
        const double sign = basis(k, peak) < 0.0 ? -1.0 : 1.0;  // deterministic: largest sample positive
        basis.row(k) *= sign / singular[k];
        if (!(singular[k] > 0.0) || !basis.row(k).allFinite()) throwTooFewComponents(plan, k);
        eigenvalues[k] = singular[k] * singular[k] / plan.trainingMaterials;
    }
    std::vector<double> values(basis.data(), basis.data() + basis.size());
    return ProfileBasis(std::move(grid.radii), std::move(grid.weights), std::move(values), std::move(eigenvalues),
                        settings.range);
}

double ProfileBasis::rMax() const { return radii_.empty() ? 0.0 : radii_.back(); }

// Linear interpolation between the stored samples r_l.
double ProfileBasis::evaluate(int k, double r) const {
    if (k < 0 || k >= K())
        throw Error("ProfileBasis::evaluate: k = " + std::to_string(k) + " outside [0, " + std::to_string(K()) + ")");
    if (!(r >= 0.0)) throw Error("ProfileBasis::evaluate: r = " + std::to_string(r) + " mm must be >= 0");
    if (r > rMax()) return 0.0;
    const std::size_t L = radii_.size();
    const std::size_t hi = std::clamp<std::size_t>(
        std::upper_bound(radii_.begin(), radii_.end(), r) - radii_.begin(), 1, L - 1);
    const double t = std::clamp((r - radii_[hi - 1]) / (radii_[hi] - radii_[hi - 1]), 0.0, 1.0);
    const double* row = values_.data() + static_cast<std::size_t>(k) * L;
    return row[hi - 1] + t * (row[hi] - row[hi - 1]);
}

// integral_a^e 2 pi r (b_a + slope (r - a)) dr on each segment [r_{l-1}, r_l] up to radius.
void ProfileBasis::diskIntegrals(double radius, std::span<double> out) const {
    if (!(radius >= 0.0))
        throw Error("ProfileBasis::diskIntegrals: radius = " + std::to_string(radius) + " mm must be >= 0");
    if (out.size() != static_cast<std::size_t>(K()))
        throw Error("ProfileBasis::diskIntegrals: " + std::to_string(out.size()) + " outputs for K = " +
                    std::to_string(K()));
    const std::size_t L = radii_.size();
    std::fill(out.begin(), out.end(), 0.0);
    for (std::size_t l = 1; l < L && radii_[l - 1] < radius; ++l) {
        const double a = radii_[l - 1], c = radii_[l], e = std::min(radius, c);
        const double square = (e * e - a * a) / 2.0, cube = (e * e * e - a * a * a) / 3.0;
        for (int k = 0; k < K(); ++k) {
            const double* row = values_.data() + static_cast<std::size_t>(k) * L;
            const double slope = (row[l] - row[l - 1]) / (c - a);
            out[static_cast<std::size_t>(k)] +=
                2.0 * std::numbers::pi * (row[l - 1] * square + slope * (cube - a * square));
        }
    }
}

// docs/ARCHITECTURE.md#pca: s0_k(sigma) = sum_l w_l R_d(r_l, sigma) b_k(r_l), the projection.
std::vector<double> ProfileBasis::unconstrainedCoefficients(const DipoleCoefficients& c) const {
    requireDipoleCoefficients(c, "ProfileBasis::coefficients");
    const std::size_t L = radii_.size();
    std::vector<double> weighted(L);
    for (std::size_t l = 0; l < L; ++l) weighted[l] = weights_[l] * dipoleProfile(radii_[l], c);
    std::vector<double> s(K());
    for (int k = 0; k < K(); ++k) {
        const double* row = values_.data() + static_cast<std::size_t>(k) * L;
        s[k] = std::inner_product(weighted.begin(), weighted.end(), row, 0.0);
    }
    return s;
}

// docs/ARCHITECTURE.md#pca, nonnegative profiles: the projection s0 reconstructs a profile
// that dips below zero in the far tail (by about 1e-7 of its peak), and a far tail summed
// over a lit region is what a shadowed sample receives, so the dip made shadowed pixels
// negative. The coefficients used are s = s0 + v with v the least-distance solution of
//     min ||v||  subject to  B (s0 + v) >= 0  and  d.v = 0,
// B: b_k(r_l) (L x K), d_k = integral_0^rMax b_k 2 pi r dr: the nearest profile in the
// weighted L2 norm (the b_k are w-orthonormal) that is nonnegative at every node and keeps
// the projection's total reflectance d.s0 (lifting the tail to zero alone would add its
// lost mass to the albedo: 3% on ketchup's blue channel). With v = N u, N an orthonormal
// basis of d's complement, it is Lawson and Hanson's least-distance problem
// min ||u|| s.t. G u >= h (G = B N, h = -B s0), solved by nonnegative least squares:
// x = argmin_{x >= 0} ||[G^T; h^T] x - e_K||, r = [G^T; h^T] x - e_K, u = -r_{<K} / r_K.
// The b_k are piecewise linear between the nodes, so a profile nonnegative at the nodes is
// nonnegative at every r.
std::vector<double> ProfileBasis::coefficients(const DipoleCoefficients& c) const {
    return nonnegative(unconstrainedCoefficients(c));
}

std::vector<double> ProfileBasis::nonnegative(std::vector<double> s) const {
    if (s.size() != std::size_t(K()))
        throw Error("ProfileBasis::nonnegative: " + std::to_string(s.size()) + " coefficients for K = " +
                    std::to_string(K()));
    const Eigen::Index L = static_cast<Eigen::Index>(radii_.size()), K = this->K();
    const Eigen::Map<const RowMatrix> Bt(values_.data(), K, L);  // row k: b_k(r_l)
    Eigen::Map<Eigen::VectorXd> s0(s.data(), K);
    const Eigen::VectorXd profile = Bt.transpose() * s0;
    if (profile.minCoeff() >= 0.0 || K < 2) return s;

    // Columns of [G^T; h^T], one per constraint, scaled by 1 / |g_l| (which leaves
    // g_l.u >= h_l unchanged) so the tail's tiny b_k weigh as much as the core's; G from
    // the frame the constructor made.
    const Eigen::Index nodes = static_cast<Eigen::Index>(frame_.nodes.size());
    const Eigen::Map<const Eigen::MatrixXd> N(frame_.complement.data(), K, K - 1);
    Eigen::MatrixXd E(K, nodes);
    E.topRows(K - 1) = Eigen::Map<const Eigen::MatrixXd>(frame_.normals.data(), K - 1, nodes);
    for (Eigen::Index j = 0; j < nodes; ++j)
        E(K - 1, j) = -profile[static_cast<Eigen::Index>(frame_.nodes[std::size_t(j)])] / frame_.norms[std::size_t(j)];
    const NnlsResult dual = nonnegativeLeastSquares(E, Eigen::VectorXd::Unit(K, K - 1));
    const Eigen::VectorXd r = E * dual.x - Eigen::VectorXd::Unit(K, K - 1);
    // Infeasible or not converged (neither seen over the editable range, which the tests
    // sweep): the plain projection, so that a material edit never fails.
    if (!dual.converged || !(std::abs(r[K - 1]) > 0.0)) return s;
    s0 += N * (-r.head(K - 1) / r[K - 1]);
    return s;
}

std::array<std::vector<double>, 3> ProfileBasis::project(const Material& m) const {
    return {coefficients(m.channel(0)), coefficients(m.channel(1)), coefficients(m.channel(2))};
}

double ProfileBasis::reconstruct(std::span<const double> s, double r) const {
    if (s.size() > static_cast<std::size_t>(K()))
        throw Error("ProfileBasis::reconstruct: " + std::to_string(s.size()) + " coefficients for a basis of K = " +
                    std::to_string(K()));
    double sum = 0.0;
    for (std::size_t k = 0; k < s.size(); ++k) sum += s[k] * evaluate(static_cast<int>(k), r);
    return sum;
}

// sqrt(sum_l w_l (R_l - sum_{k<K} s_k b_k(r_l))^2 / sum_l w_l R_l^2).
double ProfileBasis::relativeError(const DipoleCoefficients& c, int K) const {
    if (K < 0) K = this->K();
    if (K > this->K())
        throw Error("ProfileBasis::relativeError: K = " + std::to_string(K) + " exceeds the basis size " +
                    std::to_string(this->K()));
    // The full basis as renders use it; a truncated one by its plain projection.
    const std::vector<double> s = K == this->K() ? coefficients(c) : unconstrainedCoefficients(c);
    const Eigen::Index L = static_cast<Eigen::Index>(radii_.size());
    const Eigen::Map<const Eigen::VectorXd> w(weights_.data(), L);
    const Eigen::Map<const RowMatrix> b(values_.data(), this->K(), L);
    Eigen::VectorXd profile(L);
    for (Eigen::Index l = 0; l < L; ++l) profile[l] = dipoleProfile(radii_[l], c);
    const Eigen::VectorXd approx = b.topRows(K).transpose() * Eigen::Map<const Eigen::VectorXd>(s.data(), K);
    const double residual = (w.array() * (profile - approx).array().square()).sum();
    return std::sqrt(residual / (w.array() * profile.array().square()).sum());
}

}  // namespace opal
