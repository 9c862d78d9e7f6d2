// The preview delegate against the closed form of a unit sphere under a headlight: a pixel
// shows albedo x intensity x (n . v) where its ray meets the true sphere (worked out in
// sphere_scene.h from the film, independently of the delegate's camera code), so the
// centre shows the albedo itself; nothing where the ray misses; the other AOVs say where
// and what was hit.
#include "delegate/preview/preview_delegate.h"
#include "schema/error.h"
#include "tests/preview/render_preview.h"

#include <gtest/gtest.h>

namespace opal::test {
namespace {

constexpr double Albedo[3] = {0.6, 0.4, 0.2};

TEST(PreviewDelegate, TheCentreOfASphereUnderTheHeadlightShowsItsAlbedo) {
    preview::PreviewRenderDelegate delegate;
    const Frame frame = renderSphere(delegate, SphereScene());
    // Pixel (32, 24)'s centre is half a pixel off the axis: n . v = 0.99999.
    const float* centre = frame.at("color", Width / 2, Height / 2);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre[c], Albedo[c] * *sphereCosine(Width / 2, Height / 2), 2e-3) << c;
    EXPECT_EQ(centre[3], 1.0f);
}

TEST(PreviewDelegate, EveryPixelFollowsAlbedoTimesTheCosine) {
    preview::PreviewRenderDelegate delegate;
    const Frame frame = renderSphere(delegate, SphereScene(), {"color", "depth", "primId", "normal"});
    int covered = 0;
    for (int y = 0; y < Height; ++y)
        for (int x = 0; x < Width; ++x) {
            const std::optional<double> cosine = sphereCosine(x, y);
            const float* color = frame.at("color", x, y);
            // The silhouette's pixels may fall either side of the faceted mesh's outline.
            if (cosine && *cosine < 0.1) continue;
            if (!cosine) {
                EXPECT_EQ(color[3], 0.0f) << x << ", " << y;
                EXPECT_EQ(frame.at("primId", x, y)[0], -1.0f);
                EXPECT_TRUE(std::isinf(frame.at("depth", x, y)[0]));
                continue;
            }
            ++covered;
            EXPECT_EQ(color[3], 1.0f) << x << ", " << y;
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(color[c], Albedo[c] * *cosine, 5e-3) << x << ", " << y;
            EXPECT_EQ(frame.at("primId", x, y)[0], 0.0f);
        }
    EXPECT_GT(covered, 300);
    // Head on: the depth is the distance to the sphere's front, the normal points back.
    EXPECT_NEAR(frame.at("depth", Width / 2, Height / 2)[0], CameraDistance - 1.0, 2e-3);
    EXPECT_NEAR(frame.at("normal", Width / 2, Height / 2)[2], 1.0, 1e-3);
}

TEST(PreviewDelegate, TheHeadlightScalesThePictureAndNormalsShadingShowsTheNormal) {
    preview::PreviewRenderDelegate delegate({{"opal:preview:headlight", 2.0}});
    const Frame lit = renderSphere(delegate, SphereScene());
    EXPECT_NEAR(lit.at("color", Width / 2, Height / 2)[0], 2.0 * Albedo[0], 4e-3);

    delegate.setRenderSetting("opal:preview:shading", std::string("normals"));
    const Frame normals = renderSphere(delegate, SphereScene(), {"color", "normal"});
    for (const auto& [x, y] : {std::pair{32, 24}, std::pair{20, 20}, std::pair{40, 30}}) {
        const float* n = normals.at("normal", x, y);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(normals.at("color", x, y)[c], 0.5 * (n[c] + 1.0), 1e-6);
    }
}

TEST(PreviewDelegate, AMaterialPrimGivesTheAlbedo) {
    SphereScene scene;
    scene.materials[MaterialPath].subsurface = fromArtist({{0.3, 0.5, 0.7}, {2.0, 2.0, 2.0}, 1.3});
    scene.meshDesc.material = MaterialPath;
    preview::PreviewRenderDelegate delegate;
    const Frame frame = renderSphere(delegate, scene);
    const double cosine = *sphereCosine(Width / 2, Height / 2);
    EXPECT_NEAR(frame.at("color", Width / 2, Height / 2)[0], 0.3 * cosine, 2e-3);
    EXPECT_NEAR(frame.at("color", Width / 2, Height / 2)[2], 0.7 * cosine, 2e-3);
}

TEST(PreviewDelegate, RefusesOpalsLightTransportAovsNamingItsOwn) {
    preview::PreviewRenderDelegate delegate;
    EXPECT_FALSE(delegate.defaultAovDescriptor("subsurface"));
    ASSERT_TRUE(delegate.defaultAovDescriptor("color"));
    try {
        renderSphere(delegate, SphereScene(), {"color", "subsurface"});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("does not render AOV 'subsurface' (it renders color, normal, depth, primId, alpha)"),
                  std::string::npos)
            << e.what();
    }
}

TEST(PreviewDelegate, KeepsOtherDelegatesSettingsAndChecksItsOwn) {
    preview::PreviewRenderDelegate delegate;
    delegate.setRenderSetting("opal:samplesPerPixel", 64);  // a scene authored for Opal
    delegate.setRenderSetting("opal:samplesPerPixel", 16);
    EXPECT_EQ(std::get<int>(delegate.renderSetting("opal:samplesPerPixel")), 16);
    const std::vector<std::string> warnings = delegate.takeWarnings();
    ASSERT_EQ(warnings.size(), 1u);  // once per name
    EXPECT_NE(warnings[0].find("'opal:samplesPerPixel' is not the preview's: ignored"), std::string::npos) << warnings[0];
    EXPECT_THROW(delegate.setRenderSetting("opal:preview:exposure", 1.0), Error);
    EXPECT_THROW(delegate.setRenderSetting("opal:preview:shading", std::string("phong")), Error);
    EXPECT_THROW(delegate.setRenderSetting("opal:preview:headlight", -1.0), Error);
    EXPECT_EQ(std::get<double>(delegate.renderSetting("opal:preview:headlight")), 1.0);
    ASSERT_EQ(delegate.renderSettingDescriptors().size(), 2u);
    EXPECT_EQ(delegate.renderSettingDescriptors()[0].choices, (std::vector<std::string>{"lambert", "normals"}));
}

TEST(PreviewDelegate, ReportsAFrameAndWhatItHolds) {
    preview::PreviewRenderDelegate delegate;
    renderSphere(delegate, SphereScene());
    // The index is gone: its scene with it; the frame's count stays.
    EXPECT_EQ(std::get<int>(delegate.renderStats().at("passes")), 1);
    EXPECT_EQ(std::get<int>(delegate.renderStats().at("meshes")), 0);

    SphereScene scene;
    hd::RenderIndex index(delegate);
    scene.populate(index);
    index.sync();
    EXPECT_EQ(std::get<int>(delegate.renderStats().at("meshes")), 1);
    EXPECT_EQ(std::get<int>(delegate.renderStats().at("triangles")), 48 * 96 * 2);
    EXPECT_EQ(std::get<int>(delegate.renderStats().at("lightsIgnored")), 1);
}

}  // namespace
}  // namespace opal::test
