// Nonnegative least squares against a brute-force search over every support set, and its
// optimality (KKT) conditions on problems shaped like the profile projection's dual.
#include "schema/error.h"
#include "schema/scatter/nonnegative_least_squares.h"

#include <Eigen/QR>
#include <gtest/gtest.h>

#include <limits>
#include <random>

namespace opal {
namespace {

Eigen::MatrixXd randomMatrix(Eigen::Index rows, Eigen::Index cols, std::mt19937& rng) {
    std::normal_distribution<double> normal;
    Eigen::MatrixXd m(rows, cols);
    for (Eigen::Index i = 0; i < m.size(); ++i) m.data()[i] = normal(rng);
    return m;
}

// The NNLS optimum is the least-squares solution on its own support: try every support
// whose solution is nonnegative and keep the smallest residual.
Eigen::VectorXd bruteForce(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
    const Eigen::Index n = A.cols();
    Eigen::VectorXd best = Eigen::VectorXd::Zero(n);
    double bestResidual = b.squaredNorm();
    for (unsigned mask = 1; mask < (1u << n); ++mask) {
        std::vector<Eigen::Index> columns;
        for (Eigen::Index j = 0; j < n; ++j)
            if (mask & (1u << j)) columns.push_back(j);
        Eigen::MatrixXd Ap(A.rows(), Eigen::Index(columns.size()));
        for (std::size_t c = 0; c < columns.size(); ++c) Ap.col(Eigen::Index(c)) = A.col(columns[c]);
        const Eigen::VectorXd z = Ap.colPivHouseholderQr().solve(b);
        if (z.minCoeff() < 0.0) continue;
        Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
        for (std::size_t c = 0; c < columns.size(); ++c) x[columns[c]] = z[Eigen::Index(c)];
        const double residual = (A * x - b).squaredNorm();
        if (residual < bestResidual) bestResidual = residual, best = x;
    }
    return best;
}

TEST(NonnegativeLeastSquares, MatchesBruteForceOverEverySupport) {
    std::mt19937 rng(7);
    int constrained = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const Eigen::MatrixXd A = randomMatrix(8, 6, rng);
        const Eigen::VectorXd b = randomMatrix(8, 1, rng);
        const NnlsResult r = nonnegativeLeastSquares(A, b);
        ASSERT_TRUE(r.converged);
        const Eigen::VectorXd expected = bruteForce(A, b);
        EXPECT_LT((r.x - expected).norm(), 1e-9 * (1.0 + expected.norm())) << "trial " << trial;
        constrained += (A.colPivHouseholderQr().solve(b)).minCoeff() < 0.0;
    }
    EXPECT_GT(constrained, 100);  // most trials need the constraint
}

// The dual of the profile projection: few rows, many columns, the optimum on the boundary.
TEST(NonnegativeLeastSquares, WideProblemsMeetTheOptimalityConditions) {
    std::mt19937 rng(11);
    for (int trial = 0; trial < 20; ++trial) {
        const Eigen::MatrixXd A = randomMatrix(16, 256, rng);
        const Eigen::VectorXd b = randomMatrix(16, 1, rng);
        const NnlsResult r = nonnegativeLeastSquares(A, b);
        ASSERT_TRUE(r.converged);
        const Eigen::VectorXd w = A.transpose() * (b - A * r.x);
        const double scale = A.cwiseAbs().maxCoeff() * b.cwiseAbs().maxCoeff();
        EXPECT_GE(r.x.minCoeff(), 0.0);
        for (Eigen::Index j = 0; j < A.cols(); ++j) {
            EXPECT_LE(w[j], 1e-10 * scale);                                // no variable wants to grow
            if (r.x[j] > 0.0) {
                EXPECT_NEAR(w[j], 0.0, 1e-8 * scale);  // free ones sit at a minimum
            }
        }
    }
}

TEST(NonnegativeLeastSquares, RejectsMismatchedAndNonFiniteInput) {
    EXPECT_THROW(nonnegativeLeastSquares(Eigen::MatrixXd::Ones(3, 2), Eigen::VectorXd::Ones(4)), Error);
    Eigen::MatrixXd A = Eigen::MatrixXd::Ones(3, 2);
    A(1, 1) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(nonnegativeLeastSquares(A, Eigen::VectorXd::Ones(3)), Error);
}

}  // namespace
}  // namespace opal
