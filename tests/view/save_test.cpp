// What the viewer saves, against an independent truth: the scene layer it writes, rendered
// by opal-render at the same resolution and samples, gives the EXR and the PNG the viewer
// saved of its own picture (the delegate is deterministic: measured bit-exact), for an
// asset staged alone and for a scene with groups, a preset material and a light edit. The
// saved layer opens in the viewer again.
#include "examples/scene/scene_reader.h"
#include "schema/asset/shadow_field_file.h"
#include "schema/asset/shadow_field_layer.h"
#include "tests/asset/synthetic_shadow_field.h"
#include "tests/view/exr_compare.h"

#include <iostream>

namespace opal::test {
namespace {

// The viewer's EXR and PNG against opal-render's of the layer it saved: bit for bit.
void expectOpalRenderMatches(const SceneDir& dir) {
    const ViewRun render = runOpalRender(dir, shellWord(dir / "saved.usda") + " -o " + shellWord(dir / "render.exr") +
                                                  " --preview " + shellWord(dir / "render.png"));
    ASSERT_EQ(render.exitCode, 0) << render.err;
    const ReadImage viewer = readImage(dir / "viewer.exr"), truth = readImage(dir / "render.exr");
    EXPECT_EQ(truth.width, 480);
    EXPECT_EQ(truth.height, 320);
    const double exr = maxDifference(viewer, truth);
    const double png = maxDifference(readImage(dir / "viewer.png"), readImage(dir / "render.png"));
    std::cout << "viewer vs opal-render on the saved layer: EXR max difference " << exr << " over "
              << truth.channels << " channels, PNG " << png * 255.0 << " codes\n";
    EXPECT_EQ(exr, 0.0);
    EXPECT_EQ(png, 0.0);
    EXPECT_GT(channelMean(truth, "subsurface.G"), 0.0) << "the asset is lit";
}

std::string saveEverything(const SceneDir& dir) {
    return "save exr " + scriptWord(dir / "viewer.exr") + "\nsave png " + scriptWord(dir / "viewer.png") + "\nsave usda " +
           scriptWord(dir / "saved.usda") + "\n";
}

TEST(Save, TheSavedLayerOfAnEditedAssetRendersAsTheViewerShowsIt) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    // Values a float cannot hold (0.3, 0.7): the layer stores floats, and so must the edit.
    dir.write("edit.script", "load " + scriptWord(asset) +
                                 "\nmaterial set sigma_a 0.3 0.1 0.3\nmaterial set roughness 0.55\n"
                                 "light move /_OpalView/KeyLight 10.1 5 15\nlight set /_OpalView/KeyLight color 1 0.7 0.4\n"
                                 "camera orbit 25 10\n" +
                                 saveEverything(dir) + "load " + scriptWord(dir / "saved.usda") + "\nquit\n");
    const ViewRun run = runOpalView(dir, "--size 480x320 --script " + shellWord(dir / "edit.script"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    expectOpalRenderMatches(dir);
    // The viewer's own prims moved out of </_OpalView>, which a scene may not use.
    const std::string layer = slurpFile(dir / "saved.usda");
    EXPECT_EQ(layer.find("_OpalView"), std::string::npos) << layer;
    EXPECT_NE(layer.find("def SphereLight \"KeyLight\""), std::string::npos) << layer;
    EXPECT_NE(layer.find("@./sphere.usda@"), std::string::npos) << layer;
}

// A colour temperature set in the viewer warms the picture and is saved as UsdLux's
// inputs:enableColorTemperature and inputs:colorTemperature, which opal-render reads back.
TEST(Save, AColourTemperatureWarmsTheLightAndIsSaved) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    dir.write("warm.script", "load " + scriptWord(asset) + "\nsave exr " + scriptWord(dir / "white.exr") +
                                 "\nlight set /_OpalView/KeyLight temperature 2000\n" + saveEverything(dir) + "quit\n");
    const ViewRun run = runOpalView(dir, "--size 480x320 --script " + shellWord(dir / "warm.script"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    expectOpalRenderMatches(dir);
    const ReadImage white = readImage(dir / "white.exr"), warm = readImage(dir / "viewer.exr");
    const auto redOverBlue = [](const ReadImage& image) {
        return channelMean(image, "subsurface.R") / channelMean(image, "subsurface.B");
    };
    EXPECT_GT(redOverBlue(warm), 3.0 * redOverBlue(white));
    const std::string layer = slurpFile(dir / "saved.usda");
    EXPECT_NE(layer.find("float inputs:colorTemperature = 2000"), std::string::npos) << layer;

    dir.write("bad.script", "load " + scriptWord(asset) + "\nlight set /_OpalView/KeyLight temperature 100\n");
    const ViewRun bad = runOpalView(dir, "--size 160x120 --script " + shellWord(dir / "bad.script"));
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.err.find(":2: colour temperature 100 K is outside 500 to 40000 K"), std::string::npos) << bad.err;
}

// A sphere, a spot and a distant light added and shaped in the viewer (radius, cone and
// softness, angle: values a float cannot hold) change the picture, are saved as UsdLux's
// inputs, and opal-render draws the saved scene as the viewer showed it.
TEST(Save, SphereSpotAndDistantLightsWithTheirOwnParametersAreSaved) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    const std::string lights = "/_OpalView/Lights/";
    dir.write("lights.script", "load " + scriptWord(asset) + "\nlight disable /_OpalView/KeyLight\nlight add sphere " +
                                   lights + "Bulb\nlight add spot " + lights + "Spot\nlight add distant " + lights +
                                   "Sun\nlight set " + lights + "Sun intensity 1000\nsave exr " +
                                   scriptWord(dir / "unshaped.exr") + "\nlight set " + lights + "Bulb radius 0.7\n" +
                                   "light set " + lights + "Spot cone 12.3\nlight set " + lights + "Spot softness 0.35\n" +
                                   "light set " + lights + "Sun angle 3.3\n" + saveEverything(dir) + "load " +
                                   scriptWord(dir / "saved.usda") + "\nquit\n");
    const ViewRun run = runOpalView(dir, "--size 480x320 --script " + shellWord(dir / "lights.script"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    expectOpalRenderMatches(dir);
    EXPECT_GT(maxDifference(readImage(dir / "unshaped.exr"), readImage(dir / "viewer.exr")), 1e-3)
        << "the shapes change the picture";
    const std::string layer = slurpFile(dir / "saved.usda");
    for (const char* line : {"def SphereLight \"Bulb\"", "float inputs:radius = 0.7", "def SphereLight \"Spot\"",
                             "float inputs:shaping:cone:angle = 12.3", "float inputs:shaping:cone:softness = 0.35",
                             "def DistantLight \"Sun\"", "float inputs:angle = 3.3"})
        EXPECT_NE(layer.find(line), std::string::npos) << line << " in\n" << layer;

    dir.write("bad.script", "load " + scriptWord(asset) + "\nlight set /_OpalView/KeyLight cone 200\n");
    const ViewRun bad = runOpalView(dir, "--size 160x120 --script " + shellWord(dir / "bad.script"));
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.err.find(":2: cone 200 is outside 0 to 180 degrees"), std::string::npos) << bad.err;
}

// A distant light turned as a drag of 360 pixels to the right turns it (light_drag.h): a
// quarter turn about the camera's up axis, so a sun shining along the view now comes from
// the right (the saved layer's light axis, read back by the scene reader), the asset's right
// side is the bright one, and opal-render draws the saved scene as the viewer showed it.
TEST(Save, ADistantLightTurnedByADragComesFromWhereTheDragTookIt) {
    const SceneDir dir;
    dir.writeSphereAsset("sphere");
    dir.write("scene.usda", R"(#usda 1.0
(
    metersPerUnit = 0.001
)

def "Sphere" (
    references = @./sphere.usda@
)
{
}

def DistantLight "Sun"
{
}

def Camera "Camera"
{
    double3 xformOp:translate = (0, 0, 30)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
)");
    dir.write("turn.script", "light turn /Sun 360 0\n" + saveEverything(dir) + "quit\n");
    const ViewRun run = runOpalView(dir, shellWord(dir / "scene.usda") + " --size 480x320 --script " +
                                             shellWord(dir / "turn.script"));
    EXPECT_EQ(run.exitCode, 0) << run.err;
    expectOpalRenderMatches(dir);
    scene::AssetCache assets;
    const scene::Scene saved = scene::readScene(dir / "saved.usda", assets);
    const Imath::M44d& sun = saved.lights.at("/Sun").desc.transform;
    EXPECT_NEAR(sun[2][0], 1.0, 1e-6);
    EXPECT_NEAR(sun[2][1], 0.0, 1e-6);
    EXPECT_NEAR(sun[2][2], 0.0, 1e-6);
    const double side = brightSide(readImage(dir / "viewer.exr"));
    std::cout << "the turned sun's bright side: " << side << " px\n";
    EXPECT_GT(side, 5.0);

    // The timed drag turns a distant light too: its axis leaves the view's, its position stays.
    dir.write("drag.script", "drag light /Sun 2\nsave usda " + scriptWord(dir / "dragged.usda") + "\nquit\n");
    const ViewRun drag = runOpalView(dir, shellWord(dir / "scene.usda") + " --size 160x120 --script " +
                                              shellWord(dir / "drag.script"));
    ASSERT_EQ(drag.exitCode, 0) << drag.err;
    const Imath::M44d dragged = scene::readScene(dir / "dragged.usda", assets).lights.at("/Sun").desc.transform;
    EXPECT_LT(dragged[2][2], 0.999) << "turned";
    EXPECT_EQ(Imath::V3d(dragged[3][0], dragged[3][1], dragged[3][2]), Imath::V3d(0.0)) << "not moved";

    dir.write("bad.script", "light add point /Bulb\nlight turn /Bulb 10 0\n");
    const ViewRun bad = runOpalView(dir, shellWord(dir / "scene.usda") + " --size 160x120 --script " +
                                             shellWord(dir / "bad.script"));
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.err.find(":2: </Bulb> is not a distant light"), std::string::npos) << bad.err;
}

// A baked light layer (flame.usda, a field made in code with every map a uniform radiance)
// written beside `asset`, and the script lines that open the asset lit by it alone, as
// </_OpalView/Lights/Flame>.
std::string litByFlame(const SceneDir& dir, const std::filesystem::path& asset) {
    writeShadowFieldFile(dir / "flame.light.opal", uniformShadowField([](std::uint32_t, std::uint64_t) { return 0.5; }));
    writeShadowFieldLayer(dir / "flame.usda", "flame", "./flame.light.opal", std::nullopt);
    return "load " + scriptWord(asset) + "\nlight disable /_OpalView/KeyLight\nlight add shadowfield " +
           scriptWord(dir / "flame.usda") + " /_OpalView/Lights/Flame\n";
}

// A baked light layer added as a shadow-field light (here a field made in code, every map
// a uniform radiance) lights the asset alone, is saved as an OpalShadowFieldLight naming
// the field, and opal-render draws the saved scene as the viewer showed it. A missing file
// or a layer without such a light fails with its line.
TEST(Save, AShadowFieldLightAddedFromABakedLightLayerIsSaved) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    dir.write("field.script", litByFlame(dir, asset) + saveEverything(dir) + "quit\n");
    const ViewRun run = runOpalView(dir, "--size 480x320 --script " + shellWord(dir / "field.script"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    expectOpalRenderMatches(dir);
    const std::string layer = slurpFile(dir / "saved.usda");
    EXPECT_NE(layer.find("def OpalShadowFieldLight \"Flame\""), std::string::npos) << layer;
    EXPECT_NE(layer.find("@./flame.light.opal@"), std::string::npos) << layer;

    const std::filesystem::path bad = dir.write(
        "bad.script", "load " + scriptWord(asset) + "\nlight add shadowfield " + scriptWord(dir / "nowhere.usda") + "\n");
    const ViewRun missing = runOpalView(dir, "--size 160x120 --script " + shellWord(bad));
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.err.find(":2: " + (dir / "nowhere.usda").string() + ": no such light layer"), std::string::npos)
        << missing.err;
    dir.write("bad.script", "load " + scriptWord(asset) + "\nlight add shadowfield " + scriptWord(asset) + "\n");
    const ViewRun notLight = runOpalView(dir, "--size 160x120 --script " + shellWord(bad));
    EXPECT_EQ(notLight.exitCode, 1);
    EXPECT_NE(notLight.err.find(":2: " + asset.string() + ": not a baked light layer"), std::string::npos) << notLight.err;
}

// A shadow-field light's flicker set in the viewer is saved: opal-render at the same
// scene time (time code 12 at 24 per second: 0.5 s) draws the saved layer as the viewer
// showed it, and the flicker changes the picture from the steady light's. A flicker on
// another kind of light fails with its line.
TEST(Save, AShadowFieldLightsFlickerIsSaved) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    dir.write("flicker.script", litByFlame(dir, asset) + saveExr(dir, "steady.exr") +
                                    "light set /_OpalView/Lights/Flame flicker 0.9 3 7\ntime 12\n" + saveExr(dir, "viewer.exr") +
                                    "save usda " + scriptWord(dir / "saved.usda") + "\nquit\n");
    const ViewRun run = runOpalView(dir, "--size 240x160 --script " + shellWord(dir / "flicker.script"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::string layer = slurpFile(dir / "saved.usda");
    EXPECT_NE(layer.find("float opal:flicker:amplitude = 0.9"), std::string::npos) << layer;
    EXPECT_NE(layer.find("float opal:flicker:frequency = 3"), std::string::npos) << layer;
    EXPECT_NE(layer.find("int opal:flicker:seed = 7"), std::string::npos) << layer;
    const ViewRun render = runOpalRender(dir, shellWord(dir / "saved.usda") + " --time 0.5 -o " + shellWord(dir / "render.exr"));
    ASSERT_EQ(render.exitCode, 0) << render.err;
    const ReadImage viewer = readImage(dir / "viewer.exr"), steady = readImage(dir / "steady.exr");
    ASSERT_GT(channelMean(steady, "subsurface.G"), 0.0);
    const double difference = maxDifference(viewer, readImage(dir / "render.exr"));
    std::cout << "flickering light at 0.5 s, viewer vs opal-render on the saved layer: EXR max difference " << difference
              << "; vs the steady light " << maxDifference(viewer, steady) << '\n';
    EXPECT_LE(difference, 1.0 / 64.0) << "one step of the EXR's half floats at the brightest values (16 to 32)";
    EXPECT_GT(maxDifference(viewer, steady), 0.5) << "the flicker changed the light";

    const std::filesystem::path bad = dir.write(
        "bad.script", "load " + scriptWord(asset) + "\nlight set /_OpalView/KeyLight flicker 0.5 8 0\n");
    const ViewRun point = runOpalView(dir, "--size 160x120 --script " + shellWord(bad));
    EXPECT_EQ(point.exitCode, 1);
    EXPECT_NE(point.err.find(":2: only a shadow-field light flickers"), std::string::npos) << point.err;
}

TEST(Save, TheSavedLayerOfASceneKeepsItsPresetAndPlacesPrimsUnderGroups) {
    const SceneDir dir;
    dir.writeSphereAsset("sphere");
    dir.write("scene.usda", R"(#usda 1.0
(
    metersPerUnit = 0.001
)

def Xform "World"
{
    double3 xformOp:translate = (5, -2, 0)
    float xformOp:rotateY = 20
    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateY"]

    def "Sphere" (
        prepend apiSchemas = ["MaterialBindingAPI"]
        references = @./sphere.usda@
    )
    {
        rel material:binding = </World/Looks/Milk>
        double3 xformOp:translate = (1, 0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }

    def Scope "Looks"
    {
        def Material "Milk"
        {
            token opal:preset = "skimmilk"
            float opal:specularRoughness = 0.4
        }
    }

    def SphereLight "Bulb"
    {
        float inputs:intensity = 900
        bool treatAsPoint = 1
        double3 xformOp:translate = (-8, 6, 20)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
}
)");
    dir.write("edit.script", "light set /World/Bulb intensity 1234.567\ncamera orbit -15 5\n" + saveEverything(dir) +
                                 "load " + scriptWord(dir / "saved.usda") + "\nquit\n");
    const ViewRun run =
        runOpalView(dir, shellWord(dir / "scene.usda") + " --size 480x320 --script " + shellWord(dir / "edit.script"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    expectOpalRenderMatches(dir);
    const std::string layer = slurpFile(dir / "saved.usda");
    EXPECT_NE(layer.find("token opal:preset = \"skimmilk\""), std::string::npos) << layer;
    EXPECT_NE(layer.find("rel material:binding = </World/Looks/Milk>"), std::string::npos) << layer;
}

// The exact reference (opal:reference) and the samples per pixel set in the viewer: the
// picture changes, and the saved layer authors both, so opal-render draws the same.
TEST(Save, RenderSettingsChangedInTheViewerAreSavedWithTheScene) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    dir.write("settings.script", "load " + scriptWord(asset) + "\nsave exr " + scriptWord(dir / "engine.exr") +
                                     "\nsetting opal:reference true\nsetting opal:samplesPerPixel 4\n" +
                                     saveEverything(dir) + "load " + scriptWord(dir / "saved.usda") + "\nsave exr " +
                                     scriptWord(dir / "reopened.exr") + "\nquit\n");
    const ViewRun run = runOpalView(dir, "--size 480x320 --script " + shellWord(dir / "settings.script"));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_GT(maxDifference(readImage(dir / "engine.exr"), readImage(dir / "viewer.exr")), 0.0)
        << "the reference renders another picture";
    const std::string layer = slurpFile(dir / "saved.usda");
    EXPECT_NE(layer.find("bool opal:reference = 1"), std::string::npos) << layer;
    EXPECT_NE(layer.find("int opal:samplesPerPixel = 4"), std::string::npos) << layer;
    expectOpalRenderMatches(dir);
    EXPECT_EQ(maxDifference(readImage(dir / "reopened.exr"), readImage(dir / "render.exr")), 0.0);
}

TEST(Save, ASettingThatIsNotOneFailsWithItsLine) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    const std::filesystem::path script =
        dir.write("bad.script", "load " + scriptWord(asset) + "\nsetting opal:reference maybe\n");
    const ViewRun run = runOpalView(dir, "--size 160x120 --script " + shellWord(script));
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.err.find(script.string() + ":2: setting opal:reference: 'maybe' is not a bool"), std::string::npos)
        << run.err;
}

TEST(Save, APictureOrLayerThatCannotBeWrittenFailsNamingIt) {
    const SceneDir dir;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    const std::filesystem::path png = dir.write("png.script", "load " + scriptWord(asset) + "\nsave png " + scriptWord(dir / "x.jpg.txt") + "\n");
    const ViewRun badPng = runOpalView(dir, "--size 160x120 --script " + shellWord(png));
    EXPECT_EQ(badPng.exitCode, 1);
    EXPECT_NE(badPng.err.find(png.string() + ":2: save png " + (dir / "x.jpg.txt").string() + ": the file must end in .png"),
              std::string::npos)
        << badPng.err;
    const std::filesystem::path usda =
        dir.write("usda.script", "load " + scriptWord(asset) + "\nsave usda " + scriptWord(dir / "missing/saved.usda") + "\n");
    const ViewRun badUsda = runOpalView(dir, "--size 160x120 --script " + shellWord(usda));
    EXPECT_EQ(badUsda.exitCode, 1);
    EXPECT_NE(badUsda.err.find(usda.string() + ":2: " + (dir / "missing/saved.usda").string()), std::string::npos)
        << badUsda.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
}

}  // namespace
}  // namespace opal::test
