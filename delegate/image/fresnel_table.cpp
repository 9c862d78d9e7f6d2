#include "delegate/image/fresnel_table.h"

#include "schema/scatter/dipole.h"

#include <algorithm>
#include <cmath>

namespace opal {

FresnelTable::FresnelTable(double eta) : eta_(eta), tabulated_(eta >= 1.0) {
    if (!tabulated_) {
        (void)fresnelTransmittance(eta, 1.0);  // the same errors as the exact formula
        return;
    }
    for (int i = 0; i <= kIntervals; ++i) {
        const double t = double(i) / kIntervals;
        values_[std::size_t(i)] = float(fresnelTransmittance(eta, t * t));
    }
}

double FresnelTable::transmittance(double mu) const {
    if (!tabulated_) return fresnelTransmittance(eta_, mu);
    const double x = std::sqrt(std::clamp(mu, 0.0, 1.0)) * kIntervals;
    const int i = std::min(int(x), kIntervals - 1);
    const double f = x - i;
    return values_[std::size_t(i)] + (values_[std::size_t(i) + 1] - values_[std::size_t(i)]) * f;
}

}  // namespace opal
