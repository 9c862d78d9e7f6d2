// The delegate's API: prim types, render settings, AOV buffers and errors.
#include "delegate/render_delegate.h"

#include "tests/render/render_scene.h"

#include <gtest/gtest.h>

namespace opal {
namespace {

std::string messageOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(RenderDelegate, CreatesItsPrimTypesAndNothingElse) {
    OpalRenderDelegate delegate;
    EXPECT_EQ(delegate.supportedRprimTypes(), std::vector<hd::Token>{hd::PrimType::TranslucentMesh});
    EXPECT_EQ(delegate.supportedBprimTypes(), std::vector<hd::Token>{hd::PrimType::RenderBuffer});
    for (const hd::Token& type : delegate.supportedSprimTypes()) EXPECT_NE(delegate.createSprim(type, "/s"), nullptr) << type;
    EXPECT_NE(delegate.createRprim(hd::PrimType::TranslucentMesh, "/m"), nullptr);
    EXPECT_NE(delegate.createBprim(hd::PrimType::RenderBuffer, "/b"), nullptr);
    EXPECT_NE(delegate.createSprim(hd::PrimType::ShadowFieldLight, "/l"), nullptr);
    EXPECT_EQ(delegate.createSprim("rectLight", "/r"), nullptr);
    EXPECT_EQ(delegate.createRprim("basisCurves", "/c"), nullptr);
    EXPECT_EQ(delegate.createSprim(hd::PrimType::TranslucentMesh, "/m"), nullptr);

    // A host inserting an unsupported type gets a clear error from the index.
    test::CountingScene scene;
    hd::RenderIndex index(delegate);
    const std::string message = messageOf([&] { index.insertRprim("basisCurves", scene, "/World/Hair"); });
    EXPECT_TRUE(contains(message, "basisCurves") && contains(message, "/World/Hair")) << message;
}

TEST(RenderDelegate, RenderSettingsAreValidatedAndNamed) {
    OpalRenderDelegate delegate;
    const std::map<hd::Token, hd::Value> settings = delegate.renderSettings();
    ASSERT_EQ(settings.size(), 8u);
    EXPECT_EQ(std::get<int>(settings.at("opal:samplesPerPixel")), 16);
    EXPECT_EQ(std::get<std::string>(settings.at("opal:pixelFilter")), "box");
    EXPECT_EQ(std::get<bool>(settings.at("opal:reference")), false);
    EXPECT_EQ(std::get<bool>(settings.at("opal:specular")), true);
    EXPECT_EQ(std::get<bool>(settings.at("opal:transparentBackground")), false);
    EXPECT_EQ(std::get<std::string>(settings.at("opal:ocioConfig")), "");
    EXPECT_EQ(std::get<int>(settings.at("opal:tileSize")), 32);
    EXPECT_EQ(std::get<int>(settings.at("opal:draftBlock")), 1);

    delegate.setRenderSetting("opal:reference", true);
    EXPECT_EQ(std::get<bool>(delegate.renderSetting("opal:reference")), true);
    delegate.setRenderSetting("opal:tileSize", 8);
    EXPECT_EQ(delegate.settings().tileSize, 8);

    std::string m = messageOf([&] { delegate.setRenderSetting("opal:sampels", 4); });
    EXPECT_TRUE(contains(m, "unknown render setting 'opal:sampels'") && contains(m, "opal:reference")) << m;
    m = messageOf([&] { (void)delegate.renderSetting("opal:nothing"); });
    EXPECT_TRUE(contains(m, "opal:nothing")) << m;
    m = messageOf([&] { delegate.setRenderSetting("opal:specular", 1); });
    EXPECT_TRUE(contains(m, "opal:specular") && contains(m, "bool") && contains(m, "int")) << m;
    m = messageOf([&] { delegate.setRenderSetting("opal:tileSize", 0); });
    EXPECT_TRUE(contains(m, "opal:tileSize")) << m;
    EXPECT_THROW(OpalRenderDelegate({{"opal:bogus", true}}), Error);

    m = messageOf([&] { delegate.setRenderSetting("opal:pixelFilter", std::string("gauss")); });
    EXPECT_TRUE(contains(m, "gauss") && contains(m, "blackmanHarris")) << m;
    m = messageOf([&] { delegate.setRenderSetting("opal:samplesPerPixel", 0); });
    EXPECT_TRUE(contains(m, "opal:samplesPerPixel") && contains(m, "[1, 1024]")) << m;
}

TEST(RenderDelegate, AllocatesEveryAovWithItsChannels) {
    OpalRenderDelegate delegate;
    test::CountingScene scene;
    hd::RenderIndex index(delegate);
    test::addCamera(scene, index);
    index.sync();
    const test::Aovs aovs = test::renderAovs(delegate, index, test::CameraPath, 7, 5);
    const std::map<hd::Token, int> expected = {{"color", 4},  {"subsurface", 3}, {"specular", 3}, {"irradiance", 3},
                                               {"normal", 3}, {"depth", 1},      {"primId", 1},   {"alpha", 1}};
    for (const auto& [aov, channels] : expected) {
        EXPECT_EQ(aovs.channels.at(aov), channels) << aov;
        EXPECT_EQ(aovs.data.at(aov).size(), std::size_t(7 * 5 * channels)) << aov;
    }
    // An empty scene: background everywhere.
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) {
            EXPECT_EQ(aovs.at("primId", x, y)[0], -1.0f);
            EXPECT_TRUE(std::isinf(aovs.at("depth", x, y)[0]));
            EXPECT_EQ(aovs.at("alpha", x, y)[0], 0.0f);
            EXPECT_EQ(aovs.at("color", x, y)[3], 0.0f);
        }
}

TEST(RenderDelegate, RenderPassErrorsNameWhatIsWrong) {
    OpalRenderDelegate delegate;
    test::CountingScene scene;
    hd::RenderIndex index(delegate);
    test::addCamera(scene, index);
    index.sync();
    auto pass = delegate.createRenderPass(index);
    hd::RenderBuffer buffer("/b");
    hd::RenderPassState state;
    state.camera = "/World/NoSuchCamera";
    std::string m = messageOf([&] { pass->execute(state, {{"color", &buffer}}); });
    EXPECT_TRUE(contains(m, "/World/NoSuchCamera")) << m;
    state.camera = test::CameraPath;
    m = messageOf([&] { pass->execute(state, {{"beauty", &buffer}}); });
    EXPECT_TRUE(contains(m, "unknown AOV 'beauty'") && contains(m, "subsurface")) << m;
    m = messageOf([&] { pass->execute(state, {{"depth", nullptr}}); });
    EXPECT_TRUE(contains(m, "depth")) << m;
    state.width = 0;
    m = messageOf([&] { pass->execute(state, {{"color", &buffer}}); });
    EXPECT_TRUE(contains(m, test::CameraPath)) << m;
}

TEST(RenderDelegate, SyncErrorsNameThePrim) {
    OpalRenderDelegate delegate;
    test::CountingScene scene;
    hd::RenderIndex index(delegate);

    hd::CameraDesc badCamera;
    badCamera.focalLength = -1.0;
    test::addCamera(scene, index, badCamera);
    std::string m = messageOf([&] { index.sync(); });
    EXPECT_TRUE(contains(m, test::CameraPath) && contains(m, "focal length")) << m;
    scene.cameras[test::CameraPath] = test::frontCamera();
    index.sync();  // the failed prim stayed dirty and syncs now

    scene.meshes["/World/Empty"] = hd::MeshDesc{};
    index.insertRprim(hd::PrimType::TranslucentMesh, scene, "/World/Empty");
    m = messageOf([&] { index.sync(); });
    EXPECT_TRUE(contains(m, "/World/Empty") && contains(m, "no asset")) << m;
    index.removePrim("/World/Empty");

    hd::LightDesc wrongKind = test::pointLight({0, 0, 10}, 1.0);
    scene.lights["/World/Sun"] = wrongKind;
    index.insertSprim(hd::PrimType::DistantLight, scene, "/World/Sun");
    m = messageOf([&] { index.sync(); });
    EXPECT_TRUE(contains(m, "/World/Sun") && contains(m, "distant") && contains(m, "sphere")) << m;
    index.removePrim("/World/Sun");

    hd::LightDesc negative = test::pointLight({0, 0, 10}, 1.0);
    negative.radius = -1.0;
    negative.treatAsPoint = false;
    test::addLight(scene, index, "/World/Bulb", negative);
    m = messageOf([&] { index.sync(); });
    EXPECT_TRUE(contains(m, "/World/Bulb")) << m;
    index.removePrim("/World/Bulb");

    hd::MaterialDesc badMaterial;
    badMaterial.subsurface.eta = 0.5;
    scene.materials["/World/Looks/Bad"] = badMaterial;
    index.insertSprim(hd::PrimType::Material, scene, "/World/Looks/Bad");
    m = messageOf([&] { index.sync(); });
    EXPECT_TRUE(contains(m, "/World/Looks/Bad")) << m;
    index.removePrim("/World/Looks/Bad");

    // A binding to a material that is not there.
    test::addSphere(scene, index, test::SpherePath, Imath::M44d(), "/World/Looks/Missing");
    m = messageOf([&] { index.sync(); });
    EXPECT_TRUE(contains(m, test::SpherePath) && contains(m, "/World/Looks/Missing")) << m;

    // A dome on an asset without environment vectors.
    auto noEnvironment = test::sphereAsset(2, 5.0f, 0);
    scene.meshes[test::SpherePath] = hd::MeshDesc{noEnvironment, Imath::M44d(), {}, true};
    index.changeTracker().markDirty(test::SpherePath, hd::Dirty::Topology | hd::Dirty::Material);
    hd::LightDesc dome;
    dome.kind = hd::LightKind::Dome;
    test::addLight(scene, index, "/World/Sky", dome);
    m = messageOf([&] { index.sync(); });
    EXPECT_TRUE(contains(m, test::SpherePath) && contains(m, "/World/Sky") && contains(m, "environment")) << m;
    index.removePrim("/World/Sky");
    index.sync();
}

}  // namespace
}  // namespace opal
