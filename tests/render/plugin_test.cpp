// A host's path to Opal: the registry finds the opalDelegate module through the plugInfo.json
// the build wrote, loads it and creates the delegate; the host sees only the abstract API.
#include "delegate/render_delegate.h"
#include "plugin/plugin_registry.h"

#include "tests/render/render_scene.h"

#include <gtest/gtest.h>

namespace opal {
namespace {

const std::filesystem::path PluginDir = std::filesystem::path(OPAL_BINARY_DIR) / "lib/opal/plugins";

TEST(RendererPlugin, IsRegisteredAsOpal) {
    PluginRegistry registry({PluginDir});
    for (const std::string& problem : registry.problems()) ADD_FAILURE() << problem;
    const RendererPluginInfo* info = registry.findRendererPlugin("OpalRendererPlugin");
    ASSERT_NE(info, nullptr) << "no OpalRendererPlugin under " << PluginDir;
    EXPECT_EQ(info->displayName, "Opal");
    EXPECT_EQ(info->priority, 100);
    RendererPluginHandle plugin = registry.createRendererPlugin("OpalRendererPlugin");
    EXPECT_EQ(plugin->displayName(), "Opal");
    EXPECT_TRUE(plugin->isSupported());
}

TEST(RendererPlugin, CreatesDelegatesWithSettings) {
    PluginRegistry registry({PluginDir});
    RendererPluginHandle plugin = registry.createRendererPlugin("OpalRendererPlugin");
    RenderDelegateHandle delegate = plugin.createRenderDelegate({{"opal:specular", false}, {"opal:tileSize", 16}});
    EXPECT_EQ(std::get<bool>(delegate->renderSetting("opal:specular")), false);
    EXPECT_EQ(std::get<int>(delegate->renderSetting("opal:tileSize")), 16);
    try {
        plugin.createRenderDelegate({{"opal:specularity", 1.0}});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("opal:specularity"), std::string::npos) << e.what();
    }
}

TEST(RendererPlugin, RendersLikeTheDelegateItself) {
    PluginRegistry registry({PluginDir});
    RendererPluginHandle plugin = registry.createRendererPlugin("OpalRendererPlugin");
    RenderDelegateHandle loaded = plugin.createRenderDelegate();
    OpalRenderDelegate direct;

    std::vector<test::Aovs> images;
    for (hd::RenderDelegate* delegate : {loaded.get(), static_cast<hd::RenderDelegate*>(&direct)}) {
        test::CountingScene scene;
        hd::RenderIndex index(*delegate);
        test::addSphere(scene, index);
        test::addCamera(scene, index);
        test::addLight(scene, index, "/World/Key", test::pointLight({20, 4, 12}, 300.0));
        index.sync();
        images.push_back(test::renderAovs(*delegate, index, test::CameraPath, 40, 30));
    }
    const test::Aovs& a = images[0];
    EXPECT_GT(test::sumRgb(a, "color", 20, 40, 0, 30), 3.0 * test::sumRgb(a, "color", 0, 20, 0, 30));
    for (const hd::Token& aov : test::allAovs())
        EXPECT_LT(test::maxRelativeDifference(images[0].data.at(aov), images[1].data.at(aov)), 1e-6) << aov;
    EXPECT_GT(std::get<int>(loaded->renderStats().at("lightEvaluations")), 0);
}

}  // namespace
}  // namespace opal
