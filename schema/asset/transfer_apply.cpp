#include "schema/asset/transfer_apply.h"

#include "schema/error.h"
#include "schema/wavelet/cdf97.h"
#include "schema/wavelet/haar.h"

#include <string>

namespace opal {

std::vector<float> applyTransfer(const CompressedTransfer& transfer, const ChartLayout& layout,
                                 std::span<const double> s, std::span<const float> irradiance) {
    const std::size_t n = layout.cells();
    if (irradiance.size() != n) throw Error("apply transfer: irradiance has the wrong sample count");
    if (s.size() != transfer.perBasis.size()) throw Error("apply transfer: need one s_k per basis function");
    std::vector<float> wE(irradiance.begin(), irradiance.end());
    haarForwardCharts(std::span<float>(wE), layout);
    std::vector<float> sum(n, 0.0f), y(n);
    for (std::size_t k = 0; k < s.size(); ++k) {
        multiply(transfer.perBasis[k], wE, y, 1);
        for (std::size_t p = 0; p < n; ++p) sum[p] += float(s[k]) * y[p];
    }
    cdf97InverseCharts(std::span<float>(sum), layout);
    return sum;
}

}  // namespace opal
