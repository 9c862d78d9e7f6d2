// The listing hosts print (opal-render --list-delegates in detail, opal-view's picker a
// line per plugin), written out by hand from the fixture manifests: priority order, the
// current plugin marked, and a missing search path listed as skipped.
#include "plugin/plugin_listing.h"

#include "tests/plugin/fixture_plugins.h"
#include "tests/plugin/temp_dir.h"

#include <gtest/gtest.h>

namespace opal {
namespace {

using test::FixtureDir;

TEST(PluginListing, ALinePerPluginWithTheCurrentOneMarked) {
    test::TempDir dir;
    const std::filesystem::path missing = dir.path() / "missing";
    const PluginRegistry registry({FixtureDir, missing});
    EXPECT_EQ(pluginListing(registry, {.current = "OpalTestRendererPlugin"}),
              "renderer plugins (by priority, smaller first):\n"
              "  Opal Unsupported Test Renderer (OpalTestUnsupportedRendererPlugin, priority 0)\n"
              "* Opal Test Renderer (OpalTestRendererPlugin, priority 10)\n"
              "skipped:\n  " + missing.string() + ": plugin search path does not exist\n");
}

TEST(PluginListing, InDetailWithTheSearchPathsLibrariesAndManifests) {
    const PluginRegistry registry({FixtureDir});
    const std::string listing = pluginListing(registry, {.current = {}, .details = true});
    EXPECT_EQ(listing.rfind("search paths:\n  " + FixtureDir.string() +
                                "\nrenderer plugins (by priority, smaller first):\n"
                                "  OpalTestUnsupportedRendererPlugin\n",
                            0),
              0u)
        << listing;
    EXPECT_NE(listing.find("  OpalTestRendererPlugin\n    display name: Opal Test Renderer\n    priority: 10\n"
                           "    library: " + test::SupportedModule.string() + "\n    manifest: " +
                           (FixtureDir / "opalTestRenderer" / "plugInfo.json").string() + "\nskipped: none\n"),
              std::string::npos)
        << listing;
    EXPECT_EQ(pluginListing(PluginRegistry({}), {}),
              "renderer plugins (by priority, smaller first): none\nskipped: none\n");
}

}  // namespace
}  // namespace opal
