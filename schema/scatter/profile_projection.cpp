#include "schema/scatter/profile_projection.h"

#include "schema/error.h"
#include "schema/scatter/dipole.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <string>

namespace opal {

namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

}  // namespace

// G_kj = sum_{l >= first} w_l b_k(r_l) b_j(r_l) (the Gram matrix of the basis beyond rho),
// D = diag(lambda_1 / lambda_k); the inverse is made once: a material edit then costs the
// L dipole evaluations and K x L products of the plain projection plus K^2.
ProfileProjection::ProfileProjection(const ProfileBasis& basis, double innerRadius)
    : basis_(&basis), rho_(innerRadius) {
    if (basis.K() < 1) throw Error("profile projection: the basis is empty");
    if (!(innerRadius >= 0.0))
        throw Error("profile projection: inner radius " + std::to_string(innerRadius) + " mm must be >= 0");
    if (innerRadius == 0.0) return;
    const std::span<const double> r = basis.radii(), w = basis.weights(), lambda = basis.eigenvalues();
    first_ = std::size_t(std::lower_bound(r.begin(), r.end(), innerRadius) - r.begin());
    const Eigen::Index K = basis.K(), L = Eigen::Index(r.size());
    const Eigen::Map<const RowMatrix> B(basis.values().data(), K, L);  // row k: b_k(r_l)
    const Eigen::Index tail = L - Eigen::Index(first_);
    const Eigen::VectorXd wTail = Eigen::Map<const Eigen::VectorXd>(w.data() + first_, tail);
    Eigen::MatrixXd G = B.rightCols(tail) * wTail.asDiagonal() * B.rightCols(tail).transpose();
    for (Eigen::Index k = 0; k < K; ++k)
        G(k, k) += kRidge * std::max(lambda[0], 0.0) / std::max(lambda[std::size_t(k)], 1e-300 * lambda[0]);
    const RowMatrix inverse = G.ldlt().solve(Eigen::MatrixXd::Identity(K, K));
    solve_.assign(inverse.data(), inverse.data() + K * K);
}

std::vector<double> ProfileProjection::coefficients(const DipoleCoefficients& c) const {
    return basis_->nonnegative(unconstrainedCoefficients(c));
}

std::vector<double> ProfileProjection::unconstrainedCoefficients(const DipoleCoefficients& c) const {
    if (rho_ == 0.0) return basis_->unconstrainedCoefficients(c);
    requireDipoleCoefficients(c, "ProfileProjection::coefficients");
    const std::span<const double> r = basis_->radii(), w = basis_->weights();
    const Eigen::Index K = basis_->K(), L = Eigen::Index(r.size());
    Eigen::VectorXd weighted = Eigen::VectorXd::Zero(L);
    for (std::size_t l = first_; l < r.size(); ++l) weighted[Eigen::Index(l)] = w[l] * dipoleProfile(r[l], c);
    const Eigen::Map<const RowMatrix> B(basis_->values().data(), K, L);
    const Eigen::Map<const RowMatrix> inverse(solve_.data(), K, K);
    const Eigen::VectorXd s0 = inverse * (B * weighted);
    return std::vector<double>(s0.data(), s0.data() + K);
}

std::array<std::vector<double>, 3> ProfileProjection::project(const Material& m) const {
    return {coefficients(m.channel(0)), coefficients(m.channel(1)), coefficients(m.channel(2))};
}

}  // namespace opal
