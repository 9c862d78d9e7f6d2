#include "schema/scatter/profile_projection.h"

#include "schema/error.h"
#include "schema/scatter/dipole.h"

#include <Eigen/Dense>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace opal {

namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

}  // namespace

// The ridge, D = diag(mu lambda_1 / lambda_k), is made once; the Gram matrix depends on the
// material through the tail weights, so a material edit forms and solves it per channel:
// K^2 L products and a K x K factorization (tens of microseconds at K = 16, L = 256).
ProfileProjection::ProfileProjection(const ProfileBasis& basis, double innerRadius)
    : basis_(&basis), rho_(innerRadius) {
    if (basis.K() < 1) throw Error("profile projection: the basis is empty");
    if (!(innerRadius >= 0.0))
        throw Error("profile projection: inner radius " + std::to_string(innerRadius) + " mm must be >= 0");
    if (innerRadius == 0.0) return;
    const std::span<const double> r = basis.radii(), lambda = basis.eigenvalues();
    first_ = std::size_t(std::lower_bound(r.begin(), r.end(), innerRadius) - r.begin());
    tail_ = std::size_t(std::lower_bound(r.begin() + std::ptrdiff_t(first_), r.end(), kTailStart * innerRadius) -
                        r.begin());
    ridge_.resize(std::size_t(basis.K()));
    for (std::size_t k = 0; k < ridge_.size(); ++k)
        ridge_[k] = kRidge * std::max(lambda[0], 0.0) / std::max(lambda[k], 1e-300 * lambda[0]);
}

double ProfileProjection::tailEmphasis(double x) {
    if (!(x > 0.0) || !std::isfinite(x)) return 1.0;
    return std::max(1.0, std::min(1.0 / std::sqrt(x), std::sqrt(x) / kTailFloor));
}

std::vector<double> ProfileProjection::coefficients(const DipoleCoefficients& c) const {
    return basis_->nonnegative(unconstrainedCoefficients(c));
}

// The weighted ridge fit of profile_projection.h under its one constraint a . s = t:
//   G = B V B^T + D,  V = diag(w_l m_l) over l >= first (0 before),  y = G^-1 B V R_d,
//   s0 = y + z (t - a . y) / (a . z),  z = G^-1 a          (Lagrange: G s0 - B V R_d ~ a)
// with a = B u, t = u . R_d, u_l = w_l on the vanished nodes (x < f^2) and 0 elsewhere;
// without vanished nodes, s0 = y.
std::vector<double> ProfileProjection::unconstrainedCoefficients(const DipoleCoefficients& c) const {
    if (rho_ == 0.0) return basis_->unconstrainedCoefficients(c);
    requireDipoleCoefficients(c, "ProfileProjection::coefficients");
    const std::span<const double> r = basis_->radii(), w = basis_->weights();
    const Eigen::Index K = basis_->K(), L = Eigen::Index(r.size());
    const double atTail = tail_ < r.size() ? dipoleProfile(r[tail_], c) : 0.0;
    Eigen::VectorXd v = Eigen::VectorXd::Zero(L), target = Eigen::VectorXd::Zero(L), u = Eigen::VectorXd::Zero(L);
    double t = 0.0;
    for (std::size_t l = first_; l < r.size(); ++l) {
        const double profile = dipoleProfile(r[l], c);
        const double x = l >= tail_ && atTail > 0.0 ? profile / atTail : 1.0;
        v[Eigen::Index(l)] = w[l] * tailEmphasis(x);
        target[Eigen::Index(l)] = v[Eigen::Index(l)] * profile;
        if (x < kTailFloor * kTailFloor) {
            u[Eigen::Index(l)] = w[l];
            t += w[l] * profile;
        }
    }
    const Eigen::Map<const RowMatrix> B(basis_->values().data(), K, L);  // row k: b_k(r_l)
    Eigen::MatrixXd G = B * v.asDiagonal() * B.transpose();
    G.diagonal() += Eigen::Map<const Eigen::VectorXd>(ridge_.data(), K);
    const Eigen::LDLT<Eigen::MatrixXd> solver = G.ldlt();
    Eigen::VectorXd s0 = solver.solve(B * target);
    const Eigen::VectorXd a = B * u;
    if (a.squaredNorm() > 0.0) {
        const Eigen::VectorXd z = solver.solve(a);
        const double az = a.dot(z);
        if (az > 0.0) s0 += z * ((t - a.dot(s0)) / az);
    }
    return std::vector<double>(s0.data(), s0.data() + K);
}

// The three channels' fits are independent (about 0.12 ms each at K = 16, L = 256, most of
// a material edit's serial work): one task each.
std::array<std::vector<double>, 3> ProfileProjection::project(const Material& m) const {
    std::array<std::vector<double>, 3> s;
    tbb::parallel_for(0, 3, [&](int c) { s[std::size_t(c)] = coefficients(m.channel(c)); });
    return s;
}

}  // namespace opal
