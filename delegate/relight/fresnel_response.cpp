#include "delegate/relight/fresnel_response.h"

#include "schema/error.h"
#include "schema/scatter/dipole.h"
#include "schema/scatter/fresnel_moments.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace opal {

namespace {

constexpr int kNodes = 256;      // mu table intervals
constexpr int kEtaSamples = 33;  // least-squares points over the eta range

using Matrix = std::array<std::array<double, kMaxFresnelTerms>, kMaxFresnelTerms>;
using Vector = std::array<double, kMaxFresnelTerms>;

// Solves the n x n symmetric positive semi-definite system A x = b by Cholesky after a
// tiny ridge (1e-12 of the trace), which picks a well-defined solution when the range
// collapses to one eta (A has rank 1) and changes nothing measurable otherwise.
Vector solveRidge(Matrix a, Vector b, int n) {
    double trace = 0.0;
    for (int i = 0; i < n; ++i) trace += a[i][i];
    for (int i = 0; i < n; ++i) a[i][i] += 1e-12 * trace;
    for (int j = 0; j < n; ++j) {  // a = L L^T, L stored in the lower triangle
        for (int k = 0; k < j; ++k) a[j][j] -= a[j][k] * a[j][k];
        a[j][j] = std::sqrt(a[j][j]);
        for (int i = j + 1; i < n; ++i) {
            for (int k = 0; k < j; ++k) a[i][j] -= a[i][k] * a[j][k];
            a[i][j] /= a[j][j];
        }
    }
    for (int i = 0; i < n; ++i) {  // L y = b
        for (int k = 0; k < i; ++k) b[i] -= a[i][k] * b[k];
        b[i] /= a[i][i];
    }
    for (int i = n - 1; i >= 0; --i) {  // L^T x = y
        for (int k = i + 1; k < n; ++k) b[i] -= a[k][i] * b[k];
        b[i] /= a[i][i];
    }
    return b;
}

}  // namespace

FresnelResponse::FresnelResponse(double etaMin, double etaMax, int terms, FresnelBasis basis) : terms_(terms) {
    if (!(etaMin >= 1.0) || !(etaMax >= etaMin) || !std::isfinite(etaMax))
        throw Error("Fresnel response: eta range [" + std::to_string(etaMin) + ", " + std::to_string(etaMax) +
                    "] must be finite, ordered and at least 1");
    if (terms < 1 || terms > kMaxFresnelTerms)
        throw Error("Fresnel response: 1 to " + std::to_string(kMaxFresnelTerms) + " terms, got " +
                    std::to_string(terms));
    std::vector<double> etas(kEtaSamples);
    std::vector<std::vector<double>> c(kEtaSamples);
    for (int j = 0; j < kEtaSamples; ++j) {
        etas[j] = etaMin + (etaMax - etaMin) * j / (kEtaSamples - 1);
        c[j] = fresnelMoments(etas[j], terms, basis);
    }
    Matrix normal{};  // sum_j c(eta_j) c(eta_j)^T: the same for every mu
    for (int j = 0; j < kEtaSamples; ++j)
        for (int a = 0; a < terms; ++a)
            for (int b = 0; b < terms; ++b) normal[a][b] += c[j][a] * c[j][b];
    table_.resize(std::size_t(kNodes + 1) * terms);
    for (int node = 0; node <= kNodes; ++node) {
        const double mu = double(node) / kNodes;
        Vector rhs{};  // sum_j c(eta_j) F_t(eta_j, mu)
        for (int j = 0; j < kEtaSamples; ++j) {
            const double ft = fresnelTransmittance(etas[j], mu);
            for (int a = 0; a < terms; ++a) rhs[a] += c[j][a] * ft;
        }
        const Vector h = solveRidge(normal, rhs, terms);
        for (int m = 0; m < terms; ++m) table_[std::size_t(node) * terms + m] = float(h[m]);
    }
}

void FresnelResponse::evaluate(double mu, float* h) const {
    const double x = std::clamp(mu, 0.0, 1.0) * kNodes;
    const int node = std::min(int(x), kNodes - 1);
    const float t = float(x - node);
    const float* lo = table_.data() + std::size_t(node) * terms_;
    const float* hi = lo + terms_;
    for (int m = 0; m < terms_; ++m) h[m] = lo[m] + t * (hi[m] - lo[m]);
}

}  // namespace opal
