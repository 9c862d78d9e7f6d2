#include "delegate/image/fresnel_table.h"

#include "schema/scatter/dipole.h"

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

double FresnelTable::exact(double mu) const { return fresnelTransmittance(eta_, mu); }

}  // namespace opal
