// A host's whole path to a renderer: registry -> plugin -> render delegate -> render index
// -> render pass -> pixels, with only the abstract API in sight. The fixture delegate
// renders the color its settings give; these tests know that color independently.
#include "delegate/hd/render_index.h"
#include "plugin/plugin_registry.h"
#include "schema/error.h"
#include "tests/plugin/fixture_plugins.h"

#include <gtest/gtest.h>

#include <optional>

namespace opal {
namespace {

namespace fs = std::filesystem;

using test::FixtureDir;
using test::isLoaded;
using test::SupportedModule;

// A scene with one camera, as a scene source would describe it.
class CameraOnlyScene : public hd::SceneDelegate {
public:
    static constexpr double NearClip = 2.5;

    hd::MeshDesc mesh(const hd::SdfPath& id) const override { throw Error("no mesh " + id); }
    hd::MaterialDesc material(const hd::SdfPath& id) const override { throw Error("no material " + id); }
    hd::LightDesc light(const hd::SdfPath& id) const override { throw Error("no light " + id); }
    hd::CameraDesc camera(const hd::SdfPath& id) const override {
        if (id != "/World/Camera") throw Error("no camera " + id);
        hd::CameraDesc camera;
        camera.nearClip = NearClip;
        return camera;
    }
};

std::string callLog(const hd::RenderDelegate& delegate) {
    return std::get<std::string>(delegate.renderSetting("opal:test:callLog"));
}

// Renders 5 x 3 color and depth AOVs through `delegate` and checks every pixel.
void renderAndCheck(hd::RenderDelegate& delegate, float r, float g, float b) {
    CameraOnlyScene scene;
    hd::RenderIndex index(delegate);
    index.insertSprim(hd::PrimType::Camera, scene, "/World/Camera");
    index.insertBprim(hd::PrimType::RenderBuffer, scene, "/Buffers/color");
    index.insertBprim(hd::PrimType::RenderBuffer, scene, "/Buffers/depth");
    index.sync();
    auto* color = dynamic_cast<hd::RenderBuffer*>(index.bprim("/Buffers/color"));
    auto* depth = dynamic_cast<hd::RenderBuffer*>(index.bprim("/Buffers/depth"));
    ASSERT_TRUE(color && depth);

    std::unique_ptr<hd::RenderPass> pass = delegate.createRenderPass(index);
    hd::RenderPassState state;
    state.camera = "/World/Camera";
    state.width = 5;
    state.height = 3;
    pass->execute(state, {{"color", color}, {"depth", depth}});

    ASSERT_EQ(color->width(), 5);
    ASSERT_EQ(color->height(), 3);
    ASSERT_EQ(color->channels(), 4);
    ASSERT_EQ(depth->channels(), 1);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x) {
            const float* c = color->pixel(x, y);
            EXPECT_EQ(c[0], r);
            EXPECT_EQ(c[1], g);
            EXPECT_EQ(c[2], b);
            EXPECT_EQ(c[3], 1.0f);
            EXPECT_EQ(depth->pixel(x, y)[0], float(CameraOnlyScene::NearClip));
        }
}

TEST(RenderThroughPlugin, TheDelegateRendersItsSettingsIntoRenderBuffers) {
    PluginRegistry registry({FixtureDir});
    RendererPluginHandle plugin = registry.defaultRendererPlugin();
    RenderDelegateHandle delegate =
        plugin.createRenderDelegate({{"opal:test:red", 0.25}, {"opal:test:green", 0.5}, {"opal:test:blue", 1}});
    EXPECT_EQ(std::get<double>(delegate->renderSetting("opal:test:red")), 0.25);
    EXPECT_EQ(delegate->supportedSprimTypes(), std::vector<hd::Token>{hd::PrimType::Camera});

    renderAndCheck(*delegate, 0.25f, 0.5f, 1.0f);
    // The index inserted, synced (Bprims, then Sprims, as Hydra) and committed; then the
    // host made a pass and executed it.
    EXPECT_EQ(callLog(*delegate),
              "createSprim camera /World/Camera; createBprim renderBuffer /Buffers/color; "
              "createBprim renderBuffer /Buffers/depth; sync /World/Camera; commitResources; "
              "createRenderPass; execute /World/Camera");

    delegate->setRenderSetting("opal:test:green", 0.125);
    renderAndCheck(*delegate, 0.25f, 0.125f, 1.0f);
}

TEST(RenderThroughPlugin, ABadSettingIsTheDelegatesErrorAndNothingLeaks) {
    PluginRegistry registry({FixtureDir});
    RendererPluginHandle plugin = registry.createRendererPlugin("OpalTestRendererPlugin");
    EXPECT_THROW(plugin.createRenderDelegate({{"opal:test:alpha", 1.0}}), Error);
    EXPECT_THROW(plugin.createRenderDelegate({{"opal:test:red", std::string("red")}}), Error);
}

TEST(RenderThroughPlugin, TheLibraryStaysLoadedWhileAnythingFromItLives) {
    PluginRegistry registry({FixtureDir});
    ASSERT_FALSE(isLoaded(SupportedModule));
    std::optional<RenderDelegateHandle> delegate;
    {
        RendererPluginHandle plugin = registry.createRendererPlugin("OpalTestRendererPlugin");
        EXPECT_TRUE(isLoaded(SupportedModule));
        delegate.emplace(plugin.createRenderDelegate({{"opal:test:blue", 0.75}}));
    }
    // The plugin handle is gone; the delegate still runs the library's code.
    EXPECT_TRUE(isLoaded(SupportedModule));
    renderAndCheck(**delegate, 0.0f, 0.0f, 0.75f);

    // Moving a handle over another destroys the old delegate, then releases its library.
    *delegate = registry.createRendererPlugin("OpalTestRendererPlugin").createRenderDelegate();
    renderAndCheck(**delegate, 0.0f, 0.0f, 0.0f);
    delegate.reset();
    EXPECT_FALSE(isLoaded(SupportedModule));
}

}  // namespace
}  // namespace opal
