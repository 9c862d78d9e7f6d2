// Image formation: what the AOVs hold for a translucent sphere lit by point lights.
#include "delegate/render_delegate.h"

#include "tests/render/render_scene.h"

#include <gtest/gtest.h>

#include <chrono>
#include <ctime>
#include <cstdio>

namespace opal {
namespace {

constexpr int W = 64, H = 48;

// The standard scene: the sphere, the front camera and a point light on the right (+X).
struct LitSphere {
    OpalRenderDelegate delegate;
    test::CountingScene scene;
    hd::RenderIndex index{delegate};

    explicit LitSphere(const std::map<hd::Token, hd::Value>& settings = {}) : delegate(settings) {
        test::addSphere(scene, index);
        test::addCamera(scene, index);
        test::addLight(scene, index, "/World/Key", test::pointLight({20, 4, 12}, 300.0));
        index.sync();
    }
    test::Aovs render(int width = W, int height = H) {
        return test::renderAovs(delegate, index, test::CameraPath, width, height);
    }
};

TEST(Render, LitSideIsBrighterAndTheBackgroundIsExact) {
    LitSphere s;
    const test::Aovs a = s.render();
    const double left = test::sumRgb(a, "color", 0, W / 2, 0, H);
    const double right = test::sumRgb(a, "color", W / 2, W, 0, H);
    EXPECT_GT(right, 3.0 * left);
    int hits = 0;
    double coverage = 0.0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const float* color = a.at("color", x, y);
            EXPECT_EQ(color[3], a.at("alpha", x, y)[0]);
            hits += a.at("primId", x, y)[0] == 0.0f;
            coverage += a.at("alpha", x, y)[0];
            if (test::background(a, x, y)) {
                EXPECT_EQ(a.at("primId", x, y)[0], -1.0f);
                for (int c = 0; c < 4; ++c) EXPECT_EQ(color[c], 0.0f);
                EXPECT_EQ(a.at("alpha", x, y)[0], 0.0f);
                EXPECT_TRUE(std::isinf(a.at("depth", x, y)[0]));
                for (int c = 0; c < 3; ++c) EXPECT_EQ(a.at("normal", x, y)[c], 0.0f);
                continue;
            }
            if (!test::interior(a, x, y)) continue;  // a silhouette pixel: the edge tests check those
            EXPECT_EQ(color[3], 1.0f);
            EXPECT_EQ(a.at("alpha", x, y)[0], 1.0f);
            const float* n = a.at("normal", x, y);
            EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0f, 1e-4f);
            EXPECT_GT(n[2], -0.05f);  // facing the camera
            const float depth = a.at("depth", x, y)[0];
            EXPECT_GE(depth, 30.0f - 5.0f - 0.01f);
            EXPECT_LE(depth, 30.0f + 0.01f);
            for (int c = 0; c < 3; ++c) EXPECT_GE(color[c], 0.0f);
        }
    // The sphere (radius 5 at distance 30) subtends a disk of radius tan(asin(5 / 30)) on the
    // plane z = -1; the 36 mm film at 50 mm fitted into a 4:3 image shows 0.72 x 0.54 of it.
    const double radius = std::tan(std::asin(5.0 / 30.0));
    const double expected = std::numbers::pi * radius * radius / (0.72 * 0.54) * W * H;
    EXPECT_NEAR(hits, expected, 0.02 * expected);  // centre rays
    // The filtered alpha sums the pixels' covered fractions: the disk's area (less the
    // tessellation's, about 1%).
    EXPECT_NEAR(coverage, expected, 0.02 * expected);
    // The centre looks straight at the sphere's front.
    const float* centre = a.at("normal", W / 2, H / 2);
    EXPECT_NEAR(centre[2], 1.0f, 0.02f);
    EXPECT_NEAR(a.at("depth", W / 2, H / 2)[0], 25.0f, 0.05f);
    // Irradiance: lit on the right, zero on the far left (facing away from the light).
    EXPECT_GT(a.at("irradiance", W / 2 + 8, H / 2)[0], 0.1f);
    EXPECT_LT(a.at("irradiance", W / 2 - 9, H / 2)[0], 0.05f * a.at("irradiance", W / 2 + 8, H / 2)[0]);
}

TEST(Render, ColorIsSubsurfacePlusSpecular) {
    LitSphere s;
    const test::Aovs a = s.render();
    double specular = 0.0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            for (int c = 0; c < 3; ++c) {
                const float sss = a.at("subsurface", x, y)[c], spec = a.at("specular", x, y)[c];
                // Per sample exactly; the filtered average rounds each AOV on its own.
                EXPECT_NEAR(a.at("color", x, y)[c], sss + spec, 1e-6f * std::max(1.0f, sss + spec));
                specular += spec;
            }
    EXPECT_GT(specular, 0.0);  // the GGX layer is on by default
}

TEST(Render, SpecularOffLeavesTheSubsurfaceOnly) {
    LitSphere on;
    const test::Aovs withSpecular = on.render();
    LitSphere off({{"opal:specular", false}});
    const test::Aovs a = off.render();
    for (std::size_t i = 0; i < a.data.at("specular").size(); ++i) EXPECT_EQ(a.data.at("specular")[i], 0.0f);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            for (int c = 0; c < 3; ++c) EXPECT_EQ(a.at("color", x, y)[c], a.at("subsurface", x, y)[c]);
    EXPECT_EQ(a.data.at("subsurface"), withSpecular.data.at("subsurface"));

    // The same through a material with its specular layer off.
    hd::MaterialDesc matte;
    matte.subsurface = test::sharedSphere()->defaultMaterial;
    matte.specular = false;
    on.scene.materials["/World/Looks/Matte"] = matte;
    on.index.insertSprim(hd::PrimType::Material, on.scene, "/World/Looks/Matte");
    on.scene.meshes[test::SpherePath].material = "/World/Looks/Matte";
    on.index.changeTracker().markDirty(test::SpherePath, hd::Dirty::Material);
    on.index.sync();
    const test::Aovs matteImage = on.render();
    EXPECT_EQ(matteImage.data.at("specular"), a.data.at("specular"));
    EXPECT_EQ(matteImage.data.at("color"), a.data.at("color"));
}

TEST(Render, TwoLightsRenderAsTheSumOfEachAlone) {
    const hd::LightDesc key = test::pointLight({20, 4, 12}, 300.0);
    hd::LightDesc fill;
    fill.kind = hd::LightKind::Distant;
    fill.normalize = true;
    fill.intensity = 0.7;
    fill.color = {0.3, 0.5, 1.0};
    fill.transform.setAxisAngle(Imath::V3d(1, 0, 0), -0.6);  // from above and in front

    OpalRenderDelegate delegate;
    test::CountingScene scene;
    hd::RenderIndex index(delegate);
    test::addSphere(scene, index);
    test::addCamera(scene, index);
    test::addLight(scene, index, "/World/Key", key);
    index.sync();
    const test::Aovs keyOnly = test::renderAovs(delegate, index, test::CameraPath, W, H);
    test::addLight(scene, index, "/World/Fill", fill);
    index.sync();
    const test::Aovs both = test::renderAovs(delegate, index, test::CameraPath, W, H);
    index.removePrim("/World/Key");
    index.sync();
    const test::Aovs fillOnly = test::renderAovs(delegate, index, test::CameraPath, W, H);

    for (const std::string aov : {"color", "subsurface", "specular", "irradiance"}) {
        std::vector<float> sum = keyOnly.data.at(aov);
        for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += fillOnly.data.at(aov)[i];
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x)
                if (aov == "color") sum[(std::size_t(y) * W + x) * 4 + 3] = both.at(aov, x, y)[3];
        EXPECT_LT(test::maxRelativeDifference(both.data.at(aov), sum), 2e-5) << aov;
    }
}

// Renders the sphere placed at `at` with an identity camera at the origin; returns the
// centroid of the pixels it covers.
Imath::V2d centroidOfSphereAt(const Imath::V3d& at, const Imath::M44d& camera = Imath::M44d()) {
    OpalRenderDelegate delegate;
    test::CountingScene scene;
    hd::RenderIndex index(delegate);
    test::addSphere(scene, index, test::SpherePath, test::translation(at.x, at.y, at.z));
    hd::CameraDesc c;
    c.transform = camera;
    test::addCamera(scene, index, c);
    index.sync();
    const test::Aovs a = test::renderAovs(delegate, index, test::CameraPath, W, H);
    Imath::V2d sum(0.0);
    int n = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            if (a.at("primId", x, y)[0] == 0.0f) {
                sum += Imath::V2d(x + 0.5, y + 0.5);
                ++n;
            }
    EXPECT_GT(n, 0);
    return n ? sum / n : Imath::V2d(-1.0);
}

TEST(Render, CameraConventions) {
    const Imath::V2d centred = centroidOfSphereAt({0, 0, -30});
    EXPECT_NEAR(centred.x, W / 2.0, 0.5);
    EXPECT_NEAR(centred.y, H / 2.0, 0.5);
    const Imath::V2d right = centroidOfSphereAt({6, 0, -30});
    EXPECT_GT(right.x, W / 2.0 + 5.0);
    EXPECT_NEAR(right.y, H / 2.0, 0.5);
    const Imath::V2d up = centroidOfSphereAt({0, 6, -30});
    EXPECT_LT(up.y, H / 2.0 - 5.0);  // row 0 is the top
    EXPECT_NEAR(up.x, W / 2.0, 0.5);
    // A camera turned to look down -X sees an object on -X in the middle.
    Imath::M44d turned;
    turned.setAxisAngle(Imath::V3d(0, 1, 0), std::numbers::pi / 2);
    const Imath::V2d side = centroidOfSphereAt({-30, 0, 0}, turned);
    EXPECT_NEAR(side.x, W / 2.0, 0.5);
    EXPECT_NEAR(side.y, H / 2.0, 0.5);
}

TEST(Render, ReferenceModeAgreesWithTheLosslessEngine) {
    LitSphere compressed;
    hd::LightDesc fill;
    fill.kind = hd::LightKind::Distant;
    fill.normalize = true;
    fill.color = {0.3, 0.5, 1.0};
    fill.transform.setAxisAngle(Imath::V3d(1, 0, 0), -0.6);
    test::addLight(compressed.scene, compressed.index, "/World/Fill", fill);
    compressed.index.sync();
    const test::Aovs engine = compressed.render();
    EXPECT_EQ(compressed.delegate.totals().referenceGathers, 0u);

    // The same delegate switched to the reference: the pass commits the change itself.
    compressed.delegate.setRenderSetting("opal:reference", true);
    const test::Aovs reference = compressed.render();
    EXPECT_EQ(compressed.delegate.totals().referenceGathers, 1u);
    const double sss = test::maxRelativeDifference(engine.data.at("subsurface"), reference.data.at("subsurface"));
    const double e = test::maxRelativeDifference(engine.data.at("irradiance"), reference.data.at("irradiance"));
    std::printf("[ reference] lossless engine vs exact gather: subsurface max rel. diff %.2e, irradiance %.2e\n", sss, e);
    EXPECT_LT(sss, 1e-3);
    EXPECT_LT(e, 1e-3);
    EXPECT_EQ(engine.data.at("primId"), reference.data.at("primId"));
    EXPECT_EQ(engine.data.at("specular"), reference.data.at("specular"));
}

}  // namespace
}  // namespace opal
