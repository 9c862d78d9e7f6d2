// The flame's colour: black-body chromaticities against the CIE Planckian locus, and the
// flame's core hotter and whiter than its rim.
#include "schema/scatter/acescg_from_xyz.h"
#include "schema/scatter/blackbody.h"
#include "bake/light/emitter_scene.h"
#include "bake/light/flame_emitter.h"
#include "schema/error.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace opal {
namespace {

// CIE 1931 chromaticities of the Planckian locus (Wyszecki and Stiles, table 1(3.11)),
// within the analytic colour matching functions' accuracy (0.0044 at 1500 K).
TEST(Blackbody, ChromaticityFollowsThePlanckianLocus) {
    const struct {
        double kelvin, x, y;
    } locus[] = {{1500, 0.5857, 0.3931}, {2000, 0.5267, 0.4133}, {2500, 0.4770, 0.4137}, {4000, 0.3805, 0.3768},
                 {6500, 0.3135, 0.3236}};
    for (const auto& p : locus) {
        const Imath::V2d xy = blackbodyChromaticity(p.kelvin);
        EXPECT_NEAR(xy.x, p.x, 0.006) << p.kelvin;
        EXPECT_NEAR(xy.y, p.y, 0.006) << p.kelvin;
    }
}

TEST(Blackbody, AcescgHasUnitLuminanceAndWarmsAsItCools) {
    Imath::V3d previous(0.0);
    for (double k : {1200.0, 1500.0, 2000.0, 3000.0, 6500.0}) {
        const Imath::V3d c = blackbodyAcescg(k);
        EXPECT_NEAR(c.dot(kAcescgLuminance), 1.0, 1e-12) << k;
        if (k > 1200.0) {
            EXPECT_LT(c.x / c.y, previous.x / previous.y) << k;
        }
        previous = c;
    }
    // The D65 white (about 6500 K) is neutral in ACEScg after the Bradford adaptation.
    const Imath::V3d white = blackbodyAcescg(6504.0);
    EXPECT_LT(std::max({white.x, white.y, white.z}) / std::min({white.x, white.y, white.z}), 1.05);
    EXPECT_THROW(blackbodyAcescg(100.0), Error);
}

// AP1 holds the Planckian locus: every channel positive, with nothing clamped, from 500 K
// (Rec.709 would need its blue clamped below about 1600 K).
TEST(Blackbody, AcescgHoldsThePlanckianLocusUnclamped) {
    for (double k = 500.0; k <= 40000.0; k *= 1.05) {
        const Imath::V3d c = blackbodyAcescg(k);
        for (int i = 0; i < 3; ++i) EXPECT_GT(c[i], 0.0) << k << " K channel " << i;
    }
}

TEST(FlameEmitter, CoreIsWhiterAndBrighterThanRim) {
    const Emitter flame = flameEmitter(FlameShape{});
    ASSERT_EQ(flame.parts.size(), 1u);
    const EmissionProfile& emission = flame.parts[0].emission;
    const Imath::V3f normal(1.0f, 0.0f, 0.0f), point(3.0f, 5.0f, 0.0f);
    const Imath::V3f core = emission({point, -normal, normal});
    const Imath::V3f rim = emission({point, Imath::V3f(-0.1f, 0.0f, 0.995f).normalized(), normal});
    EXPECT_GT(core.y, 2.0f * rim.y);                 // brighter
    EXPECT_GT(core.z / core.x, 2.0f * rim.z / rim.x);  // whiter: more blue per red,
    EXPECT_LT(core.x / core.y, 0.8f * rim.x / rim.y);  // and less red per green
    EXPECT_GT(rim.x, rim.y);                         // the rim is orange: red over green over blue
    EXPECT_GT(rim.y, rim.z);
    // The core's colour is the core temperature's (mu = 1 at the base).
    const Imath::V3f base = emission({Imath::V3f(3.0f, 0.0f, 0.0f), -normal, normal});
    const Imath::V3d expected = blackbodyAcescg(FlameShape{}.coreKelvin);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(base[c], expected[c], 2e-3 * expected[c] + 1e-4) << c;
}

TEST(FlameEmitter, IsATeardropStandingOnTheOrigin) {
    const FlameShape shape{30.0, 5.0};
    const Emitter flame = flameEmitter(shape);
    const BoundingSphere b = boundingSphere(flame);
    EXPECT_NEAR(b.centre.y, 15.0, 1e-3);
    EXPECT_NEAR(b.centre.x, 0.0, 1e-3);
    EXPECT_NEAR(b.radius, 15.0, 1e-3);
    float widest = 0.0f, widestAt = 0.0f;
    for (const Imath::V3f& p : flame.parts[0].mesh.points)
        if (std::hypot(p.x, p.z) > widest) widest = std::hypot(p.x, p.z), widestAt = p.y;
    EXPECT_NEAR(widest, 5.0f, 0.01f);
    EXPECT_NEAR(widestAt, 7.5f, 0.5f);  // a quarter of the way up
    EXPECT_THROW(flameEmitter(FlameShape{0.0, 5.0}), Error);
}

}  // namespace
}  // namespace opal
