#include "delegate/image/fresnel_table.h"

#include "schema/error.h"
#include "schema/scatter/dipole.h"

#include <gtest/gtest.h>

#include <cmath>

namespace opal {
namespace {

TEST(FresnelTable, IsTheExactTransmittanceWithin1e5) {
    for (double eta : {1.0, 1.001, 1.3, 1.45, 1.6, 2.0, 3.0}) {
        const FresnelTable table(eta);
        double worst = 0.0;
        for (int i = 0; i <= 100000; ++i) {
            const double mu = i / 100000.0;
            worst = std::max(worst, std::abs(table.transmittance(mu) - fresnelTransmittance(eta, mu)));
        }
        EXPECT_LT(worst, 1e-5) << "eta " << eta;
        EXPECT_EQ(table.transmittance(-0.5), table.transmittance(0.0));
        EXPECT_EQ(table.transmittance(1.5), table.transmittance(1.0));
    }
}

TEST(FresnelTable, EtaBelowOneIsExactAndBadEtaIsRefused) {
    const FresnelTable below(0.8);
    for (double mu : {0.0, 0.3, 0.59, 0.61, 0.9, 1.0}) EXPECT_EQ(below.transmittance(mu), fresnelTransmittance(0.8, mu));
    EXPECT_THROW(FresnelTable(-1.0), Error);
    EXPECT_THROW(FresnelTable(std::nan("")), Error);
}

}  // namespace
}  // namespace opal
