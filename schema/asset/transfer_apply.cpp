#include "schema/asset/transfer_apply.h"

#include "schema/asset/normal_harmonics.h"
#include "schema/error.h"
#include "schema/wavelet/cdf97.h"
#include "schema/wavelet/haar.h"

#include <string>

namespace opal {

std::vector<float> applyTransfer(const CompressedTransfer& transfer, const ChartLayout& layout,
                                 std::span<const double> s, std::span<const float> irradiance,
                                 std::span<const SurfaceSample> samples) {
    const std::size_t n = layout.cells(), K = transfer.perBasis.size();
    if (irradiance.size() != n) throw Error("apply transfer: irradiance has the wrong sample count");
    if (s.size() != K) throw Error("apply transfer: need one s_k per basis function");
    const bool split = !transfer.harmonics.empty();
    const std::size_t Q = transfer.harmonicSet.count;
    if (split && (samples.size() != n || transfer.harmonics.size() != n * K * Q))
        throw Error("apply transfer: the harmonic transfer needs the " + std::to_string(n) + " samples");
    std::vector<float> wE(irradiance.begin(), irradiance.end()), a;
    if (split) {
        const HarmonicFit fit(samples, transfer.harmonicSet);
        a = fit.coefficients(irradiance, 1);
        fit.residual(irradiance, 1, a, wE, 1);
    }
    haarForwardCharts(std::span<float>(wE), layout);
    std::vector<float> sum(n, 0.0f), y(n);
    for (std::size_t k = 0; k < K; ++k) {
        multiply(transfer.perBasis[k], wE, y, 1);
        for (std::size_t p = 0; p < n; ++p) sum[p] += float(s[k]) * y[p];
    }
    if (split) {  // sum_k s_k sum_q a_q (T_k f_q), in the 9/7 domain as the products are
        std::vector<float> smooth(n, 0.0f);
        for (std::size_t o = 0; o < n; ++o)
            for (std::size_t k = 0; k < K; ++k)
                for (std::size_t q = 0; q < Q; ++q)
                    smooth[o] += float(s[k]) * a[q] * transfer.harmonics[(o * K + k) * Q + q];
        cdf97ForwardCharts(std::span<float>(smooth), layout);
        for (std::size_t p = 0; p < n; ++p) sum[p] += smooth[p];
    }
    cdf97InverseCharts(std::span<float>(sum), layout);
    return sum;
}

}  // namespace opal
