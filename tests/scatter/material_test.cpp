// Presets, the artist parameterization and the editable range.
#include "schema/error.h"
#include "schema/scatter/material.h"
#include "schema/scatter/material_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace opal {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Expects fn to throw opal::Error whose message contains every fragment.
template <typename Fn>
void expectErrorMentioning(Fn&& fn, std::initializer_list<std::string> fragments) {
    try {
        fn();
        ADD_FAILURE() << "no opal::Error thrown";
    } catch (const Error& e) {
        for (const std::string& fragment : fragments)
            EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what() << " lacks " << fragment;
    }
}

void expectRelativeNear(double actual, double expected, double tolerance, const std::string& what) {
    EXPECT_NEAR(actual / expected, 1.0, tolerance) << what << ": " << actual << " vs " << expected;
}

TEST(Presets, JensenTableValues) {
    ASSERT_EQ(jensenPresets().size(), 10u);
    const std::optional<Material> marble = findPreset("marble");
    ASSERT_TRUE(marble);
    EXPECT_EQ(marble->sigmaSPrime, Rgb(2.19, 2.62, 3.00));
    EXPECT_EQ(marble->sigmaA, Rgb(0.0021, 0.0041, 0.0071));
    EXPECT_EQ(marble->eta, 1.3);
    const std::optional<Material> ketchup = findPreset("Ketchup");
    ASSERT_TRUE(ketchup);
    EXPECT_EQ(ketchup->sigmaA, Rgb(0.061, 0.97, 1.45));
    ASSERT_TRUE(findPreset("chicken1"));
    EXPECT_EQ(findPreset("chicken1")->sigmaSPrime, Rgb(0.15, 0.21, 0.38));
    EXPECT_FALSE(findPreset("jade"));
    for (const char* name :
         {"marble", "skin1", "skin2", "ketchup", "apple", "chicken", "cream", "potato", "skimmilk", "wholemilk"}) {
        ASSERT_TRUE(findPreset(name)) << name;
        EXPECT_NO_THROW(validateMaterial(*findPreset(name), name));
    }
}

TEST(Artist, ArtistToSigmaToArtistRoundTrips) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> albedo(0.01, 0.99), logMfp(std::log(0.05), std::log(200.0)), eta(1.0, 1.8);
    for (int i = 0; i < 1000; ++i) {
        ArtistMaterial artist;
        for (int c = 0; c < 3; ++c) {
            artist.albedo[c] = albedo(rng);
            artist.meanFreePath[c] = std::exp(logMfp(rng));
        }
        artist.eta = eta(rng);
        const Material material = fromArtist(artist);
        EXPECT_NO_THROW(validateMaterial(material, "round trip"));
        const ArtistMaterial back = toArtist(material);
        for (int c = 0; c < 3; ++c) {
            expectRelativeNear(back.albedo[c], artist.albedo[c], 1e-4, "albedo");
            expectRelativeNear(back.meanFreePath[c], artist.meanFreePath[c], 1e-4, "meanFreePath");
        }
        EXPECT_EQ(back.eta, artist.eta);
    }
}

TEST(Artist, SigmaToArtistToSigmaRoundTrips) {
    std::vector<Material> materials;
    for (const NamedMaterial& preset : jensenPresets()) materials.push_back(preset.material);
    const std::vector<DipoleCoefficients> channels = sampleChannels(EditableRange::coveringPresets(), 3000, 99);
    for (std::size_t i = 0; i + 2 < channels.size(); i += 3) {
        Material m;
        for (int c = 0; c < 3; ++c) {
            m.sigmaSPrime[c] = channels[i + c].sigmaSPrime;
            m.sigmaA[c] = channels[i + c].sigmaA;
        }
        m.eta = channels[i].eta;
        materials.push_back(m);
    }
    for (const Material& m : materials) {
        const Material back = fromArtist(toArtist(m));
        for (int c = 0; c < 3; ++c) {
            expectRelativeNear(back.sigmaSPrime[c], m.sigmaSPrime[c], 1e-4, "sigmaSPrime");
            expectRelativeNear(back.sigmaA[c], m.sigmaA[c], 1e-4, "sigmaA");
        }
    }
}

TEST(Artist, AlbedoIsTheIntegratedProfileAndMeanFreePathInvertsSigmaTr) {
    // Independent of the closed form: sigma_tr from its definition, albedo as a sum.
    const Material skin = *findPreset("skin1");
    const ArtistMaterial artist = toArtist(skin);
    for (int c = 0; c < 3; ++c) {
        const double sigmaT = skin.sigmaSPrime[c] + skin.sigmaA[c];
        expectRelativeNear(artist.meanFreePath[c], 1.0 / std::sqrt(3.0 * skin.sigmaA[c] * sigmaT), 1e-12, "l_d");
        double integral = 0.0;  // midpoint rule in r = t^2 up to 400 mm: R_d 2 pi r dr
        const int n = 400000;
        for (int i = 0; i < n; ++i) {
            const double t = (i + 0.5) * 20.0 / n, r = t * t;
            integral += dipoleProfile(r, skin.channel(c)) * 2.0 * std::numbers::pi * r * 2.0 * t * 20.0 / n;
        }
        expectRelativeNear(artist.albedo[c], integral, 1e-4, "albedo");
    }
}

TEST(Artist, InvalidInputNamesParameterAndChannel) {
    const ArtistMaterial good;
    for (double bad : {0.0, 1.0, 1.2, -0.1, kNaN, kInf}) {
        ArtistMaterial a = good;
        a.albedo[1] = bad;
        expectErrorMentioning([&] { fromArtist(a); }, {"albedo.g"});
    }
    for (double bad : {0.0, -1.0, kNaN, kInf}) {
        ArtistMaterial a = good;
        a.meanFreePath[2] = bad;
        expectErrorMentioning([&] { fromArtist(a); }, {"meanFreePath.b"});
    }
    for (double bad : {0.9, kNaN}) {
        ArtistMaterial a = good;
        a.eta = bad;
        expectErrorMentioning([&] { fromArtist(a); }, {"eta"});
    }
    Material m;
    m.sigmaA[0] = kNaN;
    expectErrorMentioning([&] { toArtist(m); }, {"toArtist", "sigmaA.r"});
    expectErrorMentioning([&] { validateMaterial(m, "asset.usda"); }, {"asset.usda", "sigmaA.r"});
    m = Material{};
    m.sigmaSPrime[1] = 0.0;
    expectErrorMentioning([&] { validateMaterial(m, "ctx"); }, {"sigmaSPrime.g"});
}

TEST(EditableRange, CoveringPresetsContainsEveryPresetWithMargin) {
    const EditableRange range = EditableRange::coveringPresets();
    EXPECT_NO_THROW(range.validate("default"));
    for (const NamedMaterial& preset : jensenPresets()) {
        EXPECT_TRUE(range.contains(preset.material)) << preset.name;
        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(preset.material.sigmaSPrime[c], 1.2 * range.sigmaSPrimeMin) << preset.name;
            EXPECT_LE(preset.material.sigmaSPrime[c], range.sigmaSPrimeMax / 1.2) << preset.name;
            EXPECT_GE(preset.material.sigmaA[c], 1.2 * range.sigmaAMin) << preset.name;
            EXPECT_LE(preset.material.sigmaA[c], range.sigmaAMax / 1.2) << preset.name;
        }
        EXPECT_GT(preset.material.eta, range.etaMin);
        EXPECT_LT(preset.material.eta, range.etaMax);
    }
}

TEST(EditableRange, ClampWarnsPerClampedValue) {
    const EditableRange range{0.1, 10.0, 0.001, 1.0, 1.2, 1.6};
    Material m;
    m.sigmaSPrime = Rgb(20.0, 1.0, 0.0);  // r above, b below (zero)
    m.sigmaA = Rgb(0.01, -3.0, 0.5);      // g below
    m.eta = 1.0;                          // below
    std::vector<std::string> warnings;
    const Material out = range.clamp(m, &warnings);
    ASSERT_EQ(warnings.size(), 4u);
    EXPECT_NE(warnings[0].find("sigmaSPrime.r"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("20"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[1].find("sigmaA.g"), std::string::npos) << warnings[1];
    EXPECT_NE(warnings[2].find("sigmaSPrime.b"), std::string::npos) << warnings[2];
    EXPECT_NE(warnings[3].find("eta"), std::string::npos) << warnings[3];
    EXPECT_EQ(out.sigmaSPrime, Rgb(10.0, 1.0, 0.1));
    EXPECT_EQ(out.sigmaA, Rgb(0.01, 0.001, 0.5));
    EXPECT_EQ(out.eta, 1.2);
    EXPECT_TRUE(range.contains(out));

    warnings.clear();
    EXPECT_EQ(range.clamp(out, &warnings).sigmaSPrime, out.sigmaSPrime);
    EXPECT_TRUE(warnings.empty());
    EXPECT_NO_THROW(range.clamp(m, nullptr));
}

TEST(EditableRange, NonFiniteInputThrowsAndBadRangeIsRejected) {
    const EditableRange range = EditableRange::coveringPresets();
    Material m;
    m.sigmaA[2] = kNaN;
    expectErrorMentioning([&] { range.clamp(m, nullptr); }, {"sigmaA.b"});
    EXPECT_FALSE(range.contains(m));
    m = Material{};
    m.eta = kInf;
    expectErrorMentioning([&] { range.clamp(m, nullptr); }, {"eta"});
    const EditableRange inverted{5.0, 1.0, 0.01, 0.1, 1.2, 1.6};
    expectErrorMentioning([&] { inverted.validate("bake"); }, {"bake", "sigmaSPrime"});
    const EditableRange zero{0.1, 1.0, 0.0, 0.1, 1.2, 1.6};
    expectErrorMentioning([&] { zero.clamp(Material{}, nullptr); }, {"sigmaA"});
}

TEST(MaterialSampler, DeterministicInsideRangeAndLogUniform) {
    const EditableRange range{0.01, 100.0, 1e-4, 1.0, 1.2, 1.6};
    const std::vector<DipoleCoefficients> a = sampleChannels(range, 4000, 5), b = sampleChannels(range, 4000, 5);
    ASSERT_EQ(a.size(), 4000u);
    double meanLogS = 0.0, meanLogA = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].sigmaSPrime, b[i].sigmaSPrime);
        EXPECT_EQ(a[i].sigmaA, b[i].sigmaA);
        EXPECT_GE(a[i].sigmaSPrime, 0.01);
        EXPECT_LE(a[i].sigmaSPrime, 100.0);
        EXPECT_GE(a[i].sigmaA, 1e-4);
        EXPECT_LE(a[i].sigmaA, 1.0);
        EXPECT_GE(a[i].eta, 1.2);
        EXPECT_LE(a[i].eta, 1.6);
        meanLogS += std::log10(a[i].sigmaSPrime) / a.size();
        meanLogA += std::log10(a[i].sigmaA) / a.size();
    }
    // Log-uniform: log10 is uniform on [-2, 2] and [-4, 0]; standard error of the mean ~0.018.
    EXPECT_NEAR(meanLogS, 0.0, 0.08);
    EXPECT_NEAR(meanLogA, -2.0, 0.08);
    EXPECT_NE(sampleChannels(range, 1, 6)[0].sigmaA, a[0].sigmaA);
    EXPECT_THROW(sampleChannels(range, -1, 5), Error);
}

}  // namespace
}  // namespace opal
