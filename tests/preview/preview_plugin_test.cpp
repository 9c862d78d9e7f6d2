// The preview as hosts reach it: the registry finds the opalPreview module through the
// plugInfo.json the build wrote, after Opal (so Opal stays the default), and the delegate it
// creates renders what the one linked here renders.
#include "delegate/preview/preview_delegate.h"
#include "plugin/plugin_registry.h"
#include "tests/preview/render_preview.h"

#include <gtest/gtest.h>

namespace opal::test {
namespace {

const std::filesystem::path PluginDir = std::filesystem::path(OPAL_BINARY_DIR) / "lib/opal/plugins";

TEST(PreviewPlugin, IsRegisteredAfterOpal) {
    const PluginRegistry registry({PluginDir});
    for (const std::string& problem : registry.problems()) ADD_FAILURE() << problem;
    const RendererPluginInfo* info = registry.findRendererPlugin("OpalPreviewRendererPlugin");
    ASSERT_NE(info, nullptr) << "no OpalPreviewRendererPlugin under " << PluginDir;
    EXPECT_EQ(info->displayName, "Opal Preview");
    EXPECT_EQ(info->priority, 200);
    EXPECT_EQ(info->libraryPath, PluginDir / "opalPreview" / "opalPreview.so");
    ASSERT_GE(registry.rendererPlugins().size(), 2u);
    EXPECT_EQ(registry.rendererPlugins().back().typeName, "OpalPreviewRendererPlugin");
    EXPECT_EQ(registry.defaultRendererPlugin().info().typeName, "OpalRendererPlugin");
}

TEST(PreviewPlugin, RendersAsTheDelegateItself) {
    const PluginRegistry registry({PluginDir});
    const RendererPluginHandle plugin = registry.createRendererPlugin("OpalPreviewRendererPlugin");
    EXPECT_EQ(plugin->displayName(), "Opal Preview");
    EXPECT_TRUE(plugin->isSupported());
    RenderDelegateHandle loaded = plugin.createRenderDelegate({{"opal:preview:headlight", 0.5}});
    preview::PreviewRenderDelegate direct({{"opal:preview:headlight", 0.5}});
    const Frame a = renderSphere(*loaded, SphereScene()), b = renderSphere(direct, SphereScene());
    const auto pixels = a.aovs.at("color")->data(), expected = b.aovs.at("color")->data();
    ASSERT_EQ(pixels.size(), expected.size());
    for (std::size_t i = 0; i < pixels.size(); ++i) ASSERT_EQ(pixels[i], expected[i]) << i;
    EXPECT_NEAR(a.at("color", Width / 2, Height / 2)[1], 0.5 * 0.4, 2e-3);
}

}  // namespace
}  // namespace opal::test
