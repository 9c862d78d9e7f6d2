// Switching render delegates in opal-view. The picker's list comes from the registry (both
// delegates the build registers, in priority order, the current one marked), the script and
// --delegate choose one by type, an unknown type fails listing those there are; and the
// real viewer, switched to the preview and back, shows what each delegate's shading
// predicts: the preview's headlight Lambert (albedo x cos: the albedo itself where the
// camera looks at the sphere head on, and no bright side), then Opal's picture again,
// pixel for pixel as before the switch.
#include "examples/opal-view/core/delegate_choices.h"
#include "examples/opal-view/core/script.h"
#include "plugin/plugin_listing.h"
#include "schema/error.h"
#include "tests/render/render_scene.h"
#include "tests/view/exr_compare.h"

#include <cmath>
#include <iostream>

namespace opal::test {
namespace {

const std::filesystem::path BuildPlugins = std::filesystem::path(OPAL_BINARY_DIR) / "lib/opal/plugins";
const std::string OpalLine = "Opal (OpalRendererPlugin, priority 100)";
const std::string PreviewLine = "Opal Preview (OpalPreviewRendererPlugin, priority 200)";

TEST(DelegatePicker, ListsEveryDelegateTheRegistryFoundByPriorityWithTheCurrentMarked) {
    const PluginRegistry registry({BuildPlugins});
    const std::vector<view::DelegateChoice> choices = view::delegateChoices(registry, "OpalPreviewRendererPlugin");
    ASSERT_EQ(choices.size(), 2u);
    EXPECT_EQ(choices[0].typeName, "OpalRendererPlugin");
    EXPECT_FALSE(choices[0].current);
    EXPECT_EQ(choices[1].displayName, "Opal Preview");
    EXPECT_EQ(choices[1].priority, 200);
    EXPECT_TRUE(choices[1].current);
    EXPECT_EQ(pluginListing(registry, {.current = "OpalRendererPlugin"}),
              "renderer plugins (by priority, smaller first):\n* " + OpalLine + "\n  " + PreviewLine + "\nskipped: none\n");
}

TEST(DelegatePicker, AnUnknownTypeListsTheAvailableOnes) {
    const PluginRegistry registry({BuildPlugins});
    try {
        registry.requireRendererPlugin("Nope");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "no renderer plugin 'Nope' (available: " + OpalLine + ", " + PreviewLine +
                                             "; search paths: " + BuildPlugins.string() + ")");
    }
}

TEST(DelegatePicker, TheScriptChoosesADelegateAndPrintsThePicker) {
    const std::vector<view::ScriptAction> actions =
        view::parseScript("delegate OpalPreviewRendererPlugin\ndelegates\n", "pick.script");
    ASSERT_EQ(actions.size(), 2u);
    EXPECT_EQ(actions[0].kind, view::ActionKind::Delegate);
    EXPECT_EQ(actions[0].words, std::vector<std::string>{"OpalPreviewRendererPlugin"});
    EXPECT_EQ(actions[1].kind, view::ActionKind::Delegates);
    EXPECT_THROW(view::parseScript("delegate\n", "pick.script"), Error);
}

// The mean of a block of pixels' channel c.
double blockMean(const ReadImage& image, int cx, int cy, int half, int c) {
    double sum = 0.0;
    for (int y = cy - half; y <= cy + half; ++y)
        for (int x = cx - half; x <= cx + half; ++x) sum += image.at(x, y, c);
    return sum / ((2 * half + 1) * (2 * half + 1));
}

// The largest difference of any channel over the window's picture between the menu bar and
// the heads-up line, right of the Look panel.
double largestDifference(const ReadImage& a, const ReadImage& b) {
    double largest = 0.0;
    for (int y = 100; y < a.height - 100; ++y)
        for (int x = 400; x < a.width - 20; ++x)
            for (int c = 0; c < 3; ++c) largest = std::max(largest, double(std::abs(a.at(x, y, c) - b.at(x, y, c))));
    return largest;
}

TEST(DelegatePicker, TheViewerSwitchesToThePreviewAndBack) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    const std::string script = "load " + scriptWord(asset) +
                               "\nlight move /_OpalView/KeyLight -30 0 15\ndelegates\n" + saveExr(dir, "opal.exr") +
                               "screenshot " + scriptWord(dir / "opal-before.png") +
                               "\ndelegate OpalPreviewRendererPlugin\npanel delegates on\n" + saveExr(dir, "preview.exr") +
                               "screenshot " + scriptWord(dir / "preview.png") +
                               "\ndelegates\npanel delegates off\ndelegate OpalRendererPlugin\nwait\nscreenshot " +
                               scriptWord(dir / "opal-after.png") + "\nquit\n";
    dir.write("switch.script", script);
    const ViewRun run = runOpalView(dir, "--size 960x540 --script " + shellWord(dir / "switch.script"));
    ASSERT_EQ(run.exitCode, 0) << run.err;

    // The picker's list, before and after the switch.
    const std::size_t first = run.out.find("* " + OpalLine + "\n  " + PreviewLine + "\nskipped: none\n");
    const std::size_t second = run.out.find("  " + OpalLine + "\n* " + PreviewLine + "\nskipped: none\n");
    EXPECT_NE(first, std::string::npos) << run.out;
    EXPECT_NE(second, std::string::npos) << run.out;
    EXPECT_LT(first, second) << run.out;

    // Opal: the key light on the left makes that side bright. The preview lights from the
    // camera: no side is brighter, and the centre, where the framing camera meets the sphere
    // head on, shows the material's albedo times a cosine of 1.
    const ReadImage opal = readImage(dir / "opal.exr"), preview = readImage(dir / "preview.exr");
    const double opalSide = brightSide(opal), previewSide = brightSide(preview);
    std::cout << "bright side: Opal " << opalSide << " px, preview " << previewSide << " px\n";
    EXPECT_LT(opalSide, -5.0);
    EXPECT_LT(std::abs(previewSide), 1.0);
    const ArtistMaterial look = toArtist(testMaterial());  // the sphere's baked default
    const int cx = preview.width / 2, cy = preview.height / 2;
    const double cosine = preview.at(cx, cy, preview.channel("G")) / look.albedo[1];
    std::cout << "preview centre / albedo: " << cosine << '\n';
    EXPECT_GT(cosine, 0.97);
    EXPECT_LT(cosine, 1.0 + 1e-3);
    for (const char* channel : {"R", "B"}) {
        const double albedo = look.albedo[channel[0] == 'R' ? 0 : 2];
        EXPECT_NEAR(preview.at(cx, cy, preview.channel(channel)) / albedo, cosine, 2e-3) << channel;
    }
    // The preview's EXR holds what it renders, not Opal's light transport.
    for (const std::string& name : preview.names) EXPECT_EQ(name.find("subsurface"), std::string::npos) << name;

    // The screenshots: the preview's picture is another; Opal's after the switch back is the first.
    const ReadImage before = readImage(dir / "opal-before.png"), shown = readImage(dir / "preview.png"),
                    after = readImage(dir / "opal-after.png");
    EXPECT_GT(std::abs(blockMean(shown, 480, 270, 3, 1) - blockMean(before, 480, 270, 3, 1)), 0.05);
    EXPECT_LE(largestDifference(before, after), 1.5 / 255.0);
}

TEST(DelegatePicker, AnUnknownDelegateFailsListingTheAvailableOnes) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    const ViewRun option = runOpalView(dir, shellWord(asset) + " --delegate Nope --screenshot " + shellWord(dir / "x.png"));
    EXPECT_EQ(option.exitCode, 1);
    EXPECT_NE(option.err.find("no renderer plugin 'Nope' (available: " + OpalLine + ", " + PreviewLine +
                              "; search paths: "),
              std::string::npos)
        << option.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));

    const std::filesystem::path script = dir.write("bad.script", "load " + scriptWord(asset) + "\ndelegate Nope\nquit\n");
    const ViewRun action = runOpalView(dir, "--script " + shellWord(script));
    EXPECT_EQ(action.exitCode, 1);
    EXPECT_NE(action.err.find(script.string() + ":2: no renderer plugin 'Nope' (available: "), std::string::npos)
        << action.err;
}

// --delegate starts on the preview; an AOV it does not render is refused naming those it does.
TEST(DelegatePicker, TheCommandLineChoosesThePreview) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    const std::filesystem::path script = dir.write("aov.script", "delegates\naov normal\nwait\naov subsurface\nquit\n");
    const ViewRun run = runOpalView(dir, shellWord(asset) + " --delegate OpalPreviewRendererPlugin --size 320x240 --script " +
                                             shellWord(script));
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.out.find("* " + PreviewLine), std::string::npos) << run.out;
    EXPECT_NE(run.err.find(script.string() + ":4: the renderer Opal Preview renders no AOV 'subsurface' (it renders color, "
                                             "normal, depth, primId)"),
              std::string::npos)
        << run.err;
}

}  // namespace
}  // namespace opal::test
