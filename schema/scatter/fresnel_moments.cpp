#include "schema/scatter/fresnel_moments.h"

#include "schema/error.h"
#include "schema/scatter/dipole.h"

#include <Eigen/Dense>

#include <cmath>
#include <string>

namespace opal {

double shiftedLegendre(int m, double mu) {
    switch (m) {
        case 0: return 1.0;
        case 1: return 2.0 * mu - 1.0;
        case 2: return 6.0 * mu * mu - 6.0 * mu + 1.0;
        default: throw Error("shiftedLegendre: order " + std::to_string(m) + " is not supported");
    }
}

double fresnelBasisFunction(FresnelBasis basis, int m, double mu) {
    if (basis == FresnelBasis::Legendre) return shiftedLegendre(m, mu);
    switch (m) {
        case 0: return 1.0;
        case 1: return std::pow(1.0 - mu, 5);
        case 2: return (1.0 - mu) * (1.0 - mu);
        default: throw Error("fresnelBasisFunction: order " + std::to_string(m) + " is not supported");
    }
}

// Normal equations of the weighted fit, integrated with a 256-point midpoint rule on [0, 1]
// (F_t is smooth; the fit is a few coefficients).
std::vector<double> fresnelMoments(double eta, int terms, FresnelBasis basis) {
    if (terms < 1 || terms > kMaxFresnelTerms)
        throw Error("fresnelMoments: 1 to " + std::to_string(kMaxFresnelTerms) + " terms, got " +
                    std::to_string(terms));
    constexpr int kNodes = 256;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(terms, terms);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(terms);
    for (int q = 0; q < kNodes; ++q) {
        const double mu = (q + 0.5) / kNodes;
        const double w = mu / kNodes;
        const double f = fresnelTransmittance(eta, mu);
        for (int i = 0; i < terms; ++i) {
            const double pi = fresnelBasisFunction(basis, i, mu);
            b[i] += w * f * pi;
            for (int j = 0; j < terms; ++j) A(i, j) += w * pi * fresnelBasisFunction(basis, j, mu);
        }
    }
    const Eigen::VectorXd c = A.ldlt().solve(b);
    return std::vector<double>(c.data(), c.data() + terms);
}

}  // namespace opal
