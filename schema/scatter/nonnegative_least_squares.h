// Nonnegative least squares: x = argmin ||A x - b||_2 subject to x >= 0 (Lawson and Hanson,
// "Solving Least Squares Problems", 1974, chapter 23, algorithm NNLS). The profile
// projection uses it through its dual to keep reconstructed profiles nonnegative
// (docs/ARCHITECTURE.md#pca).
#pragma once

#include <Eigen/Core>

namespace opal {

struct NnlsResult {
    Eigen::VectorXd x;
    int iterations = 0;
    bool converged = false;  // the KKT conditions hold to the tolerance
};

// A: m x n, b: m. Active-set iterations, each a least-squares solve over the passive set
// (column-pivoting QR); at most 3n outer iterations. tolerance: the largest gradient
// component A^T (b - A x) of a variable held at 0 that still counts as optimal, relative
// to ||A||_max ||b||_inf. Throws opal::Error when sizes disagree or a value is not finite.
NnlsResult nonnegativeLeastSquares(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, double tolerance = 1e-12);

}  // namespace opal
