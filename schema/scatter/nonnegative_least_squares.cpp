#include "schema/scatter/nonnegative_least_squares.h"

#include "schema/error.h"

#include <Eigen/QR>

#include <string>
#include <vector>

namespace opal {

namespace {

// z over the passive set: the unconstrained least-squares solution on those columns,
// zero elsewhere.
Eigen::VectorXd passiveSolution(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const std::vector<bool>& passive) {
    std::vector<Eigen::Index> columns;
    for (Eigen::Index j = 0; j < A.cols(); ++j)
        if (passive[std::size_t(j)]) columns.push_back(j);
    Eigen::MatrixXd Ap(A.rows(), Eigen::Index(columns.size()));
    for (std::size_t c = 0; c < columns.size(); ++c) Ap.col(Eigen::Index(c)) = A.col(columns[c]);
    const Eigen::VectorXd zp = Ap.colPivHouseholderQr().solve(b);
    Eigen::VectorXd z = Eigen::VectorXd::Zero(A.cols());
    for (std::size_t c = 0; c < columns.size(); ++c) z[columns[c]] = zp[Eigen::Index(c)];
    return z;
}

void requireFinite(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
    if (A.rows() != b.size())
        throw Error("nonnegativeLeastSquares: A has " + std::to_string(A.rows()) + " rows but b has " +
                    std::to_string(b.size()) + " values");
    if (!A.allFinite() || !b.allFinite()) throw Error("nonnegativeLeastSquares: A or b holds a value that is not finite");
}

}  // namespace

NnlsResult nonnegativeLeastSquares(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, double tolerance) {
    requireFinite(A, b);
    const Eigen::Index n = A.cols();
    const double scale = A.cwiseAbs().maxCoeff() * b.cwiseAbs().maxCoeff();
    const double tol = tolerance * (scale > 0.0 ? scale : 1.0);
    NnlsResult result{Eigen::VectorXd::Zero(n), 0, false};
    Eigen::VectorXd& x = result.x;
    std::vector<bool> passive(std::size_t(n), false);
    for (; result.iterations < 3 * n; ++result.iterations) {
        // The variable at zero whose gradient most wants it to grow enters the passive set.
        const Eigen::VectorXd w = A.transpose() * (b - A * x);
        Eigen::Index enter = -1;
        for (Eigen::Index j = 0; j < n; ++j)
            if (!passive[std::size_t(j)] && w[j] > tol && (enter < 0 || w[j] > w[enter])) enter = j;
        if (enter < 0) {
            result.converged = true;
            return result;
        }
        passive[std::size_t(enter)] = true;
        for (Eigen::Index inner = 0;; ++inner) {
            if (inner > n) return result;  // cycling in floating point: not converged
            const Eigen::VectorXd z = passiveSolution(A, b, passive);
            // Step from x toward z as far as feasibility allows; the variable that stops the
            // step leaves (set to 0 exactly: rounding could leave it a hair above, and the
            // loop would cycle), with any other that reached 0.
            double alpha = 1.0;
            Eigen::Index blocking = -1;
            for (Eigen::Index j = 0; j < n; ++j)
                if (passive[std::size_t(j)] && z[j] <= 0.0)
                    if (const double a = x[j] / (x[j] - z[j]); a < alpha) alpha = a, blocking = j;
            if (blocking < 0) {
                x = z;
                break;
            }
            x += alpha * (z - x);
            x[blocking] = 0.0;
            for (Eigen::Index j = 0; j < n; ++j)
                if (passive[std::size_t(j)] && x[j] <= 0.0) {
                    passive[std::size_t(j)] = false;
                    x[j] = 0.0;
                }
        }
    }
    return result;
}

}  // namespace opal
