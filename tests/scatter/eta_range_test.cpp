// The dipole's eta range [1, 3] (dipole.h): every entry point of the scatter library
// refuses eta outside it with the value and the range, and the bounds themselves give a
// finite positive boundary term A(eta).
#include "schema/error.h"
#include "schema/scatter/dipole.h"
#include "schema/scatter/material.h"
#include "schema/scatter/profile_basis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string>

namespace opal {
namespace {

const double kOutside[] = {3.9, 10.0, std::numeric_limits<double>::quiet_NaN(), 0.5};

// "eta = 3.9" as the error writes it (the default stream format).
std::string shown(double eta) {
    if (std::isnan(eta)) return "eta = nan";
    std::ostringstream out;
    out << "eta = " << eta;
    return out.str();
}

void expectEtaError(const std::function<void()>& fn, double eta, const std::string& context) {
    try {
        fn();
        ADD_FAILURE() << context << ": no opal::Error for " << shown(eta);
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(shown(eta)), std::string::npos) << what;
        EXPECT_NE(what.find("[1, 3]"), std::string::npos) << what;
        EXPECT_NE(what.find(context), std::string::npos) << what;
    }
}

// A from its definition with F_dr written out here, independently of dipole.cpp.
double boundaryTermByHand(double eta) {
    const double fdr = -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta;
    return (1.0 + fdr) / (1.0 - fdr);
}

TEST(EtaRange, TheBoundsGiveAFiniteBoundaryTermAtLeastOne) {
    EXPECT_EQ(kDipoleEtaMin, 1.0);
    EXPECT_EQ(kDipoleEtaMax, 3.0);
    for (double eta = kDipoleEtaMin; eta <= kDipoleEtaMax; eta += 0.01) {
        EXPECT_NO_THROW(requireDipoleEta(eta, "scan"));
        const double a = boundaryMismatch(eta);
        EXPECT_TRUE(std::isfinite(a) && a >= 1.0) << "eta " << eta << " A " << a;
        EXPECT_NEAR(a, boundaryTermByHand(eta), 1e-12 * a);
    }
    EXPECT_NEAR(boundaryMismatch(3.0), 29.992, 1e-3);
    // Why 3 and not higher: A diverges where F_dr reaches 1, near 3.85, and is negative past it.
    EXPECT_GT(boundaryTermByHand(3.84), 1000.0);
    EXPECT_LT(boundaryTermByHand(3.9), 0.0);
}

TEST(EtaRange, TheOneCheckNamesTheValueAndTheRange) {
    for (double eta : kOutside) expectEtaError([&] { requireDipoleEta(eta, "here"); }, eta, "here");
    expectEtaError([] { requireDipoleEta(std::numeric_limits<double>::infinity(), "here"); },
                   std::numeric_limits<double>::infinity(), "here");
    EXPECT_NO_THROW(requireDipoleEta(1.0, "here"));
    EXPECT_NO_THROW(requireDipoleEta(3.0, "here"));
}

TEST(EtaRange, MaterialsRefuseEtaOutsideTheDipolesRange) {
    for (double eta : kOutside) {
        Material m = *findPreset("marble");
        m.eta = eta;
        expectEtaError([&] { validateMaterial(m, "asset.usda"); }, eta, "asset.usda");
        expectEtaError([&] { toArtist(m); }, eta, "toArtist");
        expectEtaError([&] { fromArtist(ArtistMaterial{{0.8, 0.8, 0.8}, {1.0, 1.0, 1.0}, eta}); }, eta, "fromArtist");
    }
}

TEST(EtaRange, ArtistConversionAtTheBoundsIsFiniteAndRoundTrips) {
    for (double eta : {kDipoleEtaMin, 1.3, 2.5, kDipoleEtaMax}) {
        const ArtistMaterial artist{{0.2, 0.5, 0.9}, {0.5, 1.0, 4.0}, eta};
        const Material m = fromArtist(artist);
        EXPECT_NO_THROW(validateMaterial(m, "fromArtist result"));
        const ArtistMaterial back = toArtist(m);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(back.albedo[c], artist.albedo[c], 1e-9) << "eta " << eta;
            EXPECT_NEAR(back.meanFreePath[c], artist.meanFreePath[c], 1e-9 * artist.meanFreePath[c]) << "eta " << eta;
        }
    }
}

TEST(EtaRange, EditableRangesRefuseEitherBoundOutsideAndClampOnlyInside) {
    for (double eta : kOutside) {
        EditableRange range = EditableRange::coveringPresets();
        range.etaMax = eta;
        expectEtaError([&] { range.validate("--range"); }, eta, "eta maximum");
        range = EditableRange::coveringPresets();
        range.etaMin = eta;
        expectEtaError([&] { range.validate("--range"); }, eta, "eta minimum");
        Material m;
        m.eta = eta;
        expectEtaError([&] { EditableRange::coveringPresets().clamp(m, nullptr); }, eta, "EditableRange::clamp");
    }
    EditableRange whole = EditableRange::coveringPresets();
    whole.etaMin = kDipoleEtaMin;
    whole.etaMax = kDipoleEtaMax;
    EXPECT_NO_THROW(whole.validate("--range"));
    // Inside [1, 3] but outside the editable range: clamped with a warning, as before.
    Material m;
    m.eta = 2.9;
    std::vector<std::string> warnings;
    EXPECT_EQ(EditableRange::coveringPresets().clamp(m, &warnings).eta, EditableRange::coveringPresets().etaMax);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("eta"), std::string::npos) << warnings[0];
}

TEST(EtaRange, ProfileCoefficientsRefuseEtaOutsideAndAreFiniteAtTheBounds) {
    ProfileBasisSettings settings;
    settings.K = 4;
    settings.radialSamples = 64;
    settings.trainingMaterials = 64;
    settings.range.etaMin = kDipoleEtaMin;
    settings.range.etaMax = kDipoleEtaMax;
    const ProfileBasis basis = ProfileBasis::fit(settings);
    for (double value : basis.values()) ASSERT_TRUE(std::isfinite(value));
    for (double eta : kOutside)
        expectEtaError([&] { basis.coefficients({1.0, 0.01, eta}); }, eta, "ProfileBasis::coefficients");
    for (double eta : {kDipoleEtaMin, kDipoleEtaMax})
        for (double s : basis.coefficients({1.0, 0.01, eta})) EXPECT_TRUE(std::isfinite(s)) << "eta " << eta;
}

}  // namespace
}  // namespace opal
