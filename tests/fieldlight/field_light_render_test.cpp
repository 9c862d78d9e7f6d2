// The shadow-field light in the render delegate: the emitter seen by the camera (the
// `emission` AOV, in `color`, with its own primId and depth), the lit asset, the total E
// re-formed from per-light terms (moving a light and moving it back gives the same bytes),
// and flicker at a scene time.
#include "tests/fieldlight/field_fixture.h"
#include "tests/render/render_scene.h"

#include "delegate/relight/light_flicker.h"
#include "delegate/render_delegate.h"

#include <gtest/gtest.h>

#include <cmath>

namespace opal {
namespace {

using test::kEmitterRadiance;

const hd::SdfPath FlamePath = "/World/Flame";
constexpr int kWidth = 96, kHeight = 64;

struct FieldScene {
    OpalRenderDelegate delegate;
    hd::RenderIndex index{delegate};
    test::CountingScene scene;

    explicit FieldScene(const hd::LightDesc& flame) {
        test::addSphere(scene, index);
        test::addCamera(scene, index);
        test::addLight(scene, index, FlamePath, flame);
    }
    test::Aovs render() {
        index.sync();
        return test::renderAovs(delegate, index, test::CameraPath, kWidth, kHeight);
    }
    void moveFlame(const Imath::M44d& transform) {
        scene.lights[FlamePath].transform = transform;
        index.changeTracker().markDirty(FlamePath, hd::Dirty::Transform);
    }
};

const float* centre(const test::Aovs& a, const hd::Token& aov) { return a.at(aov, kWidth / 2, kHeight / 2); }

TEST(FieldLightRender, CameraSeesTheEmitterInFrontOfTheAsset) {
    // The emitter 7 mm in front of the sphere (radius 5 at the origin), camera at z = 30.
    FieldScene s(test::fieldLightDesc(test::translation(0.0, 0.0, 12.0)));
    const test::Aovs a = s.render();
    // A uniform sphere emitter shows its radiance along every ray that meets it.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre(a, "emission")[c] / kEmitterRadiance[c], 1.0, 0.05) << c;
    EXPECT_EQ(centre(a, "primId")[0], 1.0f);                // after the one mesh
    EXPECT_NEAR(centre(a, "depth")[0], 18.0f, 0.05f);        // camera z 30 - emitter z 12
    EXPECT_EQ(centre(a, "alpha")[0], 1.0f);
    // Outside the emitter's disk the sphere shows, lit by it, with no emission.
    const int x = kWidth / 2 + 20, y = kHeight / 2;
    EXPECT_EQ(a.at("primId", x, y)[0], 0.0f);
    EXPECT_EQ(a.at("emission", x, y)[0], 0.0f);
    EXPECT_GT(a.at("subsurface", x, y)[0], 0.0f);
}

TEST(FieldLightRender, ColorIsSubsurfacePlusSpecularPlusEmissionEverywhere) {
    FieldScene s(test::fieldLightDesc(test::translation(2.0, 1.0, 10.0)));
    const test::Aovs a = s.render();
    int emitting = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const float *color = a.at("color", x, y), *sub = a.at("subsurface", x, y), *spec = a.at("specular", x, y),
                        *em = a.at("emission", x, y);
            emitting += em[0] > 0.0f;
            for (int c = 0; c < 3; ++c) {
                const float sum = sub[c] + spec[c] + em[c];
                EXPECT_NEAR(color[c], sum, 2e-3f * std::max(1.0f, sum)) << x << "," << y << " channel " << c;
                EXPECT_GE(em[c], 0.0f);
                EXPECT_TRUE(std::isfinite(color[c]));
            }
        }
    EXPECT_GT(emitting, 50);
}

TEST(FieldLightRender, EmitterBehindTheAssetIsHidden) {
    FieldScene s(test::fieldLightDesc(test::translation(0.0, 0.0, -9.0)));
    const test::Aovs a = s.render();
    EXPECT_EQ(centre(a, "primId")[0], 0.0f);
    EXPECT_EQ(centre(a, "emission")[0], 0.0f);
    EXPECT_EQ(centre(a, "emission")[2], 0.0f);
}

TEST(FieldLightRender, MovingTheLightAndBackGivesTheSameBytes) {
    const Imath::M44d home = test::translation(3.0, 2.0, 11.0);
    FieldScene s(test::fieldLightDesc(home));
    test::addLight(s.scene, s.index, "/World/Key", test::pointLight({-20.0, 10.0, 20.0}, 300.0));
    const test::Aovs before = s.render();
    s.moveFlame(test::translation(-4.0, 0.0, 9.0));
    const test::Aovs moved = s.render();
    EXPECT_NE(moved.data.at("subsurface"), before.data.at("subsurface"));
    s.moveFlame(home);
    const test::Aovs back = s.render();
    for (const auto& [aov, values] : before.data) EXPECT_EQ(back.data.at(aov), values) << aov;
}

TEST(FieldLightRender, FlickerScalesTheEmitterAtTheSceneTime) {
    hd::LightDesc flame = test::fieldLightDesc(test::translation(0.0, 0.0, 12.0));
    flame.flicker = {0.4, 6.0, 3};
    double emitted[2] = {}, expected[2] = {};
    const double times[2] = {0.10, 0.37};
    for (int i = 0; i < 2; ++i) {
        flame.time = times[i];
        FieldScene s(flame);
        emitted[i] = centre(s.render(), "emission")[0];
        expected[i] = lightFlicker(flame.flicker, times[i]).intensity;
    }
    ASSERT_GT(std::abs(expected[0] - expected[1]), 0.05);  // the two times differ visibly
    EXPECT_NEAR(emitted[1] / emitted[0], expected[1] / expected[0], 0.02 * expected[1] / expected[0]);
}

TEST(FieldLightRender, AMissingFieldFileIsAnErrorNamingTheLight) {
    hd::LightDesc flame = test::fieldLightDesc(Imath::M44d());
    flame.shadowField = (test::sphereField().dir / "missing.opal").string();
    OpalRenderDelegate delegate;
    hd::RenderIndex index(delegate);
    test::CountingScene scene;
    test::addLight(scene, index, FlamePath, flame);
    try {
        index.sync();
        FAIL() << "a missing light sidecar synced";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("/World/Flame"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("missing.opal"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace opal
