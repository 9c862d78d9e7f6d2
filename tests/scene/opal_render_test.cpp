// opal-render end to end, as a pipeline runs it: a small translucent asset on disk, a scene
// referencing it with a point light and a camera, the executable run as a process. The EXR
// must read back (OpenImageIO) with Opal's channels, the working space's metadata and lit
// pixels; a malformed scene must exit 1 naming file:line:column and leave no file behind.
#include "bake/bake_pipeline.h"
#include "tests/scene/candle_scene_assets.h"
#include "tests/scene/opal_render_process.h"
#include "tests/scene/scene_test_files.h"
#include "tests/support/scene_usda.h"
#include "tests/render/render_scene.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <array>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace opal::scene {
namespace {

// The 5 mm sphere at the origin, a point light in front of it, a camera 30 mm away.
std::string litScene(const std::string& intensity) {
    using namespace test::usda;
    return header() + reference("Sphere", "./sphere.usda") + pointLight("Bulb", intensity, translate({0, 5, 20})) +
           camera("Camera", translate({0, 0, 30})) + renderSettings(48, 32);
}

std::vector<std::string> channelNames(const OIIO::ImageSpec& spec) {
    std::vector<std::string> names(spec.channelnames.begin(), spec.channelnames.end());
    std::sort(names.begin(), names.end());
    return names;
}

TEST(OpalRender, FramesWriteOneNumberedFilePairPerTimeCode) {
    const test::SceneDir dir;
    dir.writeSphereAsset("sphere");
    std::string scene = litScene("2000");
    const std::string units = "    metersPerUnit = 0.001\n";
    scene.replace(scene.find(units), units.size(), units + "    timeCodesPerSecond = 10\n");
    dir.write("scene.usda", scene);
    const ProcessResult run = runOpalRender(dir, "'" + (dir / "scene.usda").string() + "' -o '" +
                                                     (dir / "seq.exr").string() + "' --preview '" +
                                                     (dir / "seq.png").string() + "' --frames 1:5 --step 2");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    for (int frame : {1, 3, 5}) {
        const std::string stem = "seq.000" + std::to_string(frame);
        ASSERT_TRUE(std::filesystem::exists(dir / (stem + ".png"))) << stem;
        auto in = OIIO::ImageInput::open((dir / (stem + ".exr")).string());
        ASSERT_TRUE(in) << stem;
        EXPECT_FLOAT_EQ(in->spec().get_float_attribute("opal/time"), float(frame) / 10.0f) << stem;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "seq.0002.exr"));
    EXPECT_FALSE(std::filesystem::exists(dir / "seq.exr"));

    const ProcessResult backwards =
        runOpalRender(dir, "'" + (dir / "scene.usda").string() + "' -o x.exr --frames 5:1");
    EXPECT_EQ(backwards.exitCode, 2);
    EXPECT_NE(backwards.err.find("--frames '5:1': END is before START"), std::string::npos) << backwards.err;
    EXPECT_EQ(runOpalRender(dir, "'" + (dir / "scene.usda").string() + "' -o x.exr --frames 1:2 --time 3").exitCode, 2);
    EXPECT_EQ(runOpalRender(dir, "'" + (dir / "scene.usda").string() + "' -o x.exr --frames 1-2").exitCode, 2);
}

// A light moved by time samples renders, at each frame, what a still scene with the
// light where the samples put it renders: frame 3 of samples at frames 1 and 5 is halfway.
TEST(OpalRender, AnAnimatedLightRendersAsTheStillSceneAtEachFrame) {
    const test::SceneDir dir;
    dir.writeSphereAsset("sphere");
    std::string animated = litScene("2000");
    const std::string still = "    double3 xformOp:translate = (0, 5, 20)\n";
    animated.replace(animated.find(still), still.size(),
                     "    double3 xformOp:translate.timeSamples = {\n        1: (-20, 5, 20),\n"
                     "        5: (20, 5, 20),\n    }\n");
    const std::string units = "    metersPerUnit = 0.001\n";
    animated.replace(animated.find(units), units.size(), units + "    timeCodesPerSecond = 10\n");
    dir.write("animated.usda", animated);
    dir.write("still.usda", litScene("2000"));
    const ProcessResult run = runOpalRender(dir, "'" + (dir / "animated.usda").string() + "' -o '" +
                                                     (dir / "seq.exr").string() + "' --frames 1:3 --step 2");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const ProcessResult reference =
        runOpalRender(dir, "'" + (dir / "still.usda").string() + "' -o '" + (dir / "still.exr").string() + "'");
    ASSERT_EQ(reference.exitCode, 0) << reference.err;

    const std::vector<float> first = exrPixels(dir / "seq.0001.exr"), third = exrPixels(dir / "seq.0003.exr"),
                             expected = exrPixels(dir / "still.exr");
    ASSERT_FALSE(expected.empty());
    ASSERT_EQ(third.size(), expected.size());
    double largest = 0.0, difference = 0.0, frameDifference = 0.0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        if (!std::isfinite(expected[i])) {  // the background's depth
            EXPECT_EQ(third[i], expected[i]) << i;
            continue;
        }
        largest = std::max(largest, double(std::abs(expected[i])));
        difference = std::max(difference, double(std::abs(third[i] - expected[i])));
        frameDifference = std::max(frameDifference, double(std::abs(first[i] - expected[i])));
    }
    EXPECT_LE(difference, 1e-6 * largest);
    EXPECT_GT(frameDifference, 0.05 * largest);  // frame 1 lights the sphere from the left
}

TEST(OpalRender, WritesALitMultiLayerExrAndAPreview) {
    const test::SceneDir dir;
    dir.writeSphereAsset("sphere");
    dir.write("scene.usda", litScene("2000"));
    const ProcessResult run = runOpalRender(dir, "'" + (dir / "scene.usda").string() + "' -o '" + (dir / "out.exr").string() +
                                           "' --preview '" + (dir / "out.png").string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("48x32"), std::string::npos) << run.out;

    auto in = OIIO::ImageInput::open((dir / "out.exr").string());
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec spec = in->spec();
    EXPECT_EQ(spec.width, 48);
    EXPECT_EQ(spec.height, 32);
    const std::vector<std::string> expected = {
        "A",          "B",          "G",          "R",          "depth.Z",      "emission.B",   "emission.G",
        "emission.R", "irradiance.B", "irradiance.G", "irradiance.R", "normal.X", "normal.Y", "normal.Z",
        "primId.id", "specular.B", "specular.G", "specular.R", "subsurface.B", "subsurface.G", "subsurface.R"};
    EXPECT_EQ(channelNames(spec), expected);
    EXPECT_EQ(spec.get_string_attribute("oiio:ColorSpace"), "ACEScg");
    EXPECT_EQ(spec.get_string_attribute("opal/scene"), (dir / "scene.usda").string());
    EXPECT_EQ(spec.get_string_attribute("opal/resolution"), "48x32");

    std::vector<float> pixels(std::size_t(spec.width) * spec.height * spec.nchannels);
    ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
    const auto value = [&](int x, int y, const std::string& channel) {
        const int c = spec.channelindex(channel);
        return pixels[(std::size_t(y) * spec.width + x) * spec.nchannels + c];
    };
    // The sphere (radius 5 at distance 30 through a 50 mm lens) covers the centre; the
    // corners see the background.
    EXPECT_GT(value(24, 16, "R"), 0.0f);
    EXPECT_GT(value(24, 16, "subsurface.R"), 0.0f);
    EXPECT_GT(value(24, 16, "irradiance.R"), 0.0f);
    EXPECT_FLOAT_EQ(value(24, 16, "A"), 1.0f);
    EXPECT_FLOAT_EQ(value(24, 16, "primId.id"), 0.0f);
    EXPECT_FLOAT_EQ(value(0, 0, "A"), 0.0f);
    EXPECT_FLOAT_EQ(value(0, 0, "primId.id"), -1.0f);
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "out.png"));
    // Anti-aliased: the sphere's silhouette has fractional alpha, and colour is premultiplied
    // by it (the header says so).
    int fractional = 0;
    for (int y = 0; y < spec.height; ++y)
        for (int x = 0; x < spec.width; ++x) {
            const float alpha = value(x, y, "A");
            if (alpha > 0.0f && alpha < 1.0f) ++fractional;
            if (alpha == 0.0f) {
                EXPECT_EQ(value(x, y, "R"), 0.0f);
            }
        }
    EXPECT_GT(fractional, 10);
    EXPECT_NE(spec.get_string_attribute("opal/alpha").find("premultiplied"), std::string::npos);
}

// Each row of the AOV table (hd/aov.h) is an --aov choice, written as the row says: its
// EXR channels and pixel type. Nothing here names an AOV.
TEST(OpalRender, EveryAovOfTheTableIsWrittenAsItsRowSays) {
    const test::SceneDir dir;
    dir.writeSphereAsset("sphere");
    dir.write("scene.usda", litScene("2000"));
    for (const hd::AovDescriptor& aov : hd::aovTable()) {
        const std::filesystem::path exr = dir / (aov.name + ".exr");
        const ProcessResult run = runOpalRender(
            dir, "'" + (dir / "scene.usda").string() + "' -o '" + exr.string() + "' --aov " + aov.name);
        ASSERT_EQ(run.exitCode, 0) << aov.name << ": " << run.err;
        auto in = OIIO::ImageInput::open(exr.string());
        ASSERT_TRUE(in) << OIIO::geterror();
        const OIIO::ImageSpec& spec = in->spec();
        ASSERT_EQ(spec.nchannels, aov.channelCount()) << aov.name;
        for (int c = 0; c < spec.nchannels; ++c) {
            std::string expected(aov.channels[c]);
            if (!aov.exrLayer.empty()) expected.insert(0, std::string(aov.exrLayer) + ".");
            EXPECT_NE(std::find(spec.channelnames.begin(), spec.channelnames.end(), expected), spec.channelnames.end())
                << aov.name << " has no channel " << expected;
            const OIIO::TypeDesc type = spec.channelformat(c);
            EXPECT_EQ(type, aov.format == hd::AovFormat::Float32 ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::HALF)
                << aov.name;
        }
    }
}

// The shipped demo scene on its candle, wick and flame baked here with small counts
// (candle_scene_assets.h): the flame lights the melt pool, the dim dome the rest.
TEST(OpalRender, RendersTheCandleDemoOnABakedCandle) {
    const test::SceneDir dir;
    test::writeCandleScene(dir);
    const ProcessResult run = runOpalRender(dir, "'" + (dir / "candlelight.usda").string() + "' -o '" +
                                                     (dir / "candle.exr").string() + "' --resolution 96x64");
    ASSERT_EQ(run.exitCode, 0) << run.err;

    auto in = OIIO::ImageInput::open((dir / "candle.exr").string());
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec spec = in->spec();
    ASSERT_EQ(spec.width, 96);
    ASSERT_EQ(spec.height, 64);
    EXPECT_EQ(spec.nchannels, 21);
    EXPECT_EQ(spec.get_string_attribute("opal/camera"), "/World/Camera");
    std::vector<float> pixels(std::size_t(spec.width) * spec.height * spec.nchannels);
    ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
    const int r = spec.channelindex("subsurface.R"), a = spec.channelindex("A"), id = spec.channelindex("primId.id");
    int candle = 0, lit = 0;
    for (std::size_t p = 0; p < std::size_t(spec.width) * spec.height; ++p) {
        const float* px = &pixels[p * spec.nchannels];
        if (px[id] != 0.0f) continue;
        ++candle;
        EXPECT_EQ(px[a], 1.0f);
        if (px[r] > 0.0f) ++lit;
    }
    EXPECT_GT(candle, 96 * 64 / 20);  // the candle fills a good part of the frame
    // Lit, though not everywhere: at 512 samples with 1% of the Haar coefficients kept, the
    // compressed transfer leaves dark blotches (a property of such a small bake).
    EXPECT_GT(lit, candle / 10);

    // What a person sees: the flame (the emitter, primId 2 after the candle and the wick) is
    // the brightest thing in the picture, and the wax glows more toward the top.
    const auto channels = [&](const std::string& layer) {
        const std::string prefix = layer.empty() ? "" : layer + ".";
        return std::array<int, 3>{spec.channelindex(prefix + "R"), spec.channelindex(prefix + "G"),
                                  spec.channelindex(prefix + "B")};
    };
    const std::array<int, 3> color = channels(""), subsurface = channels("subsurface");
    const auto luminance = [](const float* px, const std::array<int, 3>& c) { return px[c[0]] + px[c[1]] + px[c[2]]; };
    std::size_t brightest = 0;
    for (std::size_t p = 0; p < std::size_t(spec.width) * spec.height; ++p)
        if (luminance(&pixels[p * spec.nchannels], color) > luminance(&pixels[brightest * spec.nchannels], color))
            brightest = p;
    EXPECT_EQ(pixels[brightest * spec.nchannels + id], 2.0f) << "the brightest pixel is not the flame";
    int top = spec.height, bottom = -1;
    for (int y = 0; y < spec.height; ++y)
        for (int x = 0; x < spec.width; ++x)
            if (pixels[(std::size_t(y) * spec.width + x) * spec.nchannels + id] == 0.0f) {
                top = std::min(top, y);
                bottom = std::max(bottom, y);
            }
    ASSERT_GT(bottom - top, 12);
    const auto bandMean = [&](int y0, int y1) {
        double sum = 0.0;
        int n = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < spec.width; ++x) {
                const float* px = &pixels[(std::size_t(y) * spec.width + x) * spec.nchannels];
                if (px[id] != 0.0f) continue;
                sum += luminance(px, subsurface);
                ++n;
            }
        return n ? sum / n : 0.0;
    };
    // The glow falls off down the top of the body (the flame's light carried down through
    // the wax from the rim and the pool: the outer wall faces away from the flame and gets
    // none directly), and the lower half is lit by the room alone, darker than all of it.
    const int eighth = (bottom - top + 1) / 8;
    std::array<double, 8> band{};
    for (int k = 0; k < 8; ++k) band[k] = bandMean(top + k * eighth, top + (k + 1) * eighth);
    const double lowerHalf = (band[4] + band[5] + band[6] + band[7]) / 4.0;
    EXPECT_GT(band[0], band[1]);
    EXPECT_GT(band[1], band[2]);
    EXPECT_GT(band[2], lowerHalf);
    std::printf("candle subsurface by eighths, top to bottom:");
    for (double b : band) std::printf(" %.4g", b);
    std::printf("\n");
}

TEST(OpalRender, SelectedAovsOnly) {
    const test::SceneDir dir;
    dir.writeSphereAsset("sphere");
    dir.write("scene.usda", litScene("2000"));
    const ProcessResult run = runOpalRender(dir, "'" + (dir / "scene.usda").string() + "' -o '" + (dir / "out.exr").string() +
                                           "' --aov depth --aov alpha --resolution 16x8 --material ketchup --float --reference");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    auto in = OIIO::ImageInput::open((dir / "out.exr").string());
    ASSERT_TRUE(in) << OIIO::geterror();
    EXPECT_EQ(channelNames(in->spec()), (std::vector<std::string>{"A", "depth.Z"}));
    EXPECT_EQ(in->spec().width, 16);
    EXPECT_EQ(in->spec().get_string_attribute("opal/material"), "ketchup");
    EXPECT_EQ(in->spec().get_int_attribute("opal/reference", -1), 1);
    EXPECT_EQ(in->spec().format, OIIO::TypeDesc::FLOAT);  // --float: no half channel left
}

// The delegate's warnings (a material clamped into the asset's editable range) reach the
// user through the plugin interface, and the frame is still written.
TEST(OpalRender, ReportsTheDelegatesWarnings) {
    const test::SceneDir dir;
    dir.writeSphereAsset("sphere");
    std::string scene = litScene("2000");
    scene.replace(scene.find("def \"Sphere\" (\n"), std::string("def \"Sphere\" (\n").size(),
                  "def \"Sphere\" (\n    prepend apiSchemas = [\"MaterialBindingAPI\"]\n");
    scene.replace(scene.find("{\n}\n"), 4, "{\n    rel material:binding = </Glass>\n}\n");
    scene += R"(
def Material "Glass"
{
    token opal:preset = "marble"
    float opal:eta = 2.9
}
)";
    dir.write("scene.usda", scene);
    const ProcessResult run = runOpalRender(dir, "'" + (dir / "scene.usda").string() + "' -o '" + (dir / "out.exr").string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("opal-render: warning:"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("/Glass"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("eta"), std::string::npos) << run.err;
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "out.exr"));
}

TEST(OpalRender, MalformedSceneExitsOneAndWritesNothing) {
    const test::SceneDir dir;
    dir.writeSphereAsset("sphere");
    dir.write("scene.usda", litScene("-1"));
    const ProcessResult run = runOpalRender(dir, "'" + (dir / "scene.usda").string() + "' -o '" + (dir / "out.exr").string() +
                                           "' --preview '" + (dir / "out.png").string() + "'");
    EXPECT_EQ(run.exitCode, 1);
    // Line 14, column 5: "    float inputs:intensity = -1" in the light.
    EXPECT_NE(run.err.find((dir / "scene.usda").string() +
                           ":14:5: SphereLight </Bulb>: attribute 'inputs:intensity' is -1, expected a value >= 0"),
              std::string::npos)
        << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

// Hostile input never ends in an abort, NaN or a half-written file: each is refused with
// the prim or file and what is wrong, exit 1, nothing written.
void expectRefused(const test::SceneDir& dir, std::initializer_list<std::string> parts) {
    const ProcessResult run = runOpalRender(dir, "'" + (dir / "scene.usda").string() + "' -o '" +
                                                     (dir / "out.exr").string() + "' --preview '" +
                                                     (dir / "out.png").string() + "'");
    EXPECT_EQ(run.exitCode, 1) << run.err;
    for (const std::string& part : parts) EXPECT_NE(run.err.find(part), std::string::npos) << run.err << "lacks " << part;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

// Each input finite and in its own range, the product beyond what Opal can sum in float.
TEST(OpalRender, LightsWhoseRadianceOverflowsAreRefusedNamingPrimAndAttributes) {
    const test::SceneDir dir;
    dir.writeSphereAsset("sphere");
    const std::string intensity = "    float inputs:intensity = 1\n";
    const std::vector<std::string> lights = {
        "    float inputs:intensity = 3e38\n",
        "    float inputs:intensity = 1\n    float inputs:exposure = 200\n",
        "    float inputs:intensity = 1\n    color3f inputs:color = (3e38, 3e38, 3e38)\n",
    };
    for (const std::string& light : lights) {
        std::string scene = litScene("1");
        scene.replace(scene.find(intensity), intensity.size(), light);
        dir.write("scene.usda", scene);
        expectRefused(dir, {"light '/Bulb'", "inputs:intensity", "inputs:exposure", "inputs:color",
                            "the largest emitted radiance Opal renders"});
    }
}

TEST(OpalRender, AnAssetPointOutOfRangeIsRefusedNamingFilePrimAndIndex) {
    const test::SceneDir dir;
    TranslucentAsset sphere = *test::sphereAsset(2, 5.0f, 0);
    sphere.mesh.points[3].x = 3.4e38f;  // finite, and would make every shadow ray's origin infinite
    writeSidecar(dir / "sphere.opal", sphere);
    writeAssetLayer(dir / "sphere.usda", sphere, "./sphere.opal");
    dir.write("scene.usda", litScene("2000"));
    expectRefused(dir, {(dir / "sphere.usda").string() + ":", "prim '" + sphere.name + "'", "point 3 (3.4e+38",
                        "beyond the 1e9 mm"});
}

TEST(OpalRender, ADomeTextureWithABadTexelIsRefusedNamingFileAndTexel) {
    const test::SceneDir dir;
    dir.writeSphereAsset("sphere");
    for (const float bad : {std::nanf(""), -1.0f, std::numeric_limits<float>::infinity()}) {
        std::vector<float> rgb(4 * 2 * 3, 0.5f);
        rgb[(1 * 4 + 2) * 3 + 1] = bad;  // texel (2, 1), green
        auto out = OIIO::ImageOutput::create("env.exr");
        ASSERT_TRUE(out);
        ASSERT_TRUE(out->open((dir / "env.exr").string(), OIIO::ImageSpec(4, 2, 3, OIIO::TypeDesc::FLOAT)));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()));
        out->close();
        std::string scene = litScene("2000");
        scene += "def DomeLight \"Sky\"\n{\n    asset inputs:texture:file = @./env.exr@\n}\n";
        dir.write("scene.usda", scene);
        expectRefused(dir, {"light '/Sky'", "env.exr", "texel (2, 1) channel 1"});
    }
}

// The brightest light Opal accepts, a hair above the surface: the specular layer's
// irradiance saturates (1e25) and every radiometric AOV stays finite and non-negative.
TEST(OpalRender, TheBrightestAcceptedLightAtTheSurfaceRendersFiniteValues) {
    const test::SceneDir dir;
    dir.writeSphereAsset("sphere");
    std::string scene = litScene("9e19");  // 1e20 as a float is just above 1e20
    const std::string at = "(0, 5, 20)";
    scene.replace(scene.find(at), at.size(), "(0, 0, 5.001)");  // facing the camera
    dir.write("scene.usda", scene);
    const ProcessResult run = runOpalRender(dir, "'" + (dir / "scene.usda").string() + "' -o '" +
                                                     (dir / "out.exr").string() + "' --float");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    auto in = OIIO::ImageInput::open((dir / "out.exr").string());
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec spec = in->spec();
    std::vector<float> pixels(std::size_t(spec.width) * spec.height * spec.nchannels);
    ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
    int lit = 0;
    for (int c = 0; c < spec.nchannels; ++c) {
        const std::string& name = spec.channelnames[c];
        if (name.rfind("normal.", 0) == 0 || name.rfind("depth.", 0) == 0 || name.rfind("primId.", 0) == 0) continue;
        for (std::size_t p = 0; p < std::size_t(spec.width) * spec.height; ++p) {
            const float v = pixels[p * spec.nchannels + std::size_t(c)];
            ASSERT_TRUE(std::isfinite(v) && v >= 0.0f) << name << " at pixel " << p << " is " << v;
            if (name == "R" && v > 0.0f) ++lit;  // the highlight: the samples all face away
        }
    }
    EXPECT_GT(lit, 0);
}

TEST(OpalRender, BadCommandLineExitsTwo) {
    const test::SceneDir dir;
    dir.write("scene.usda", litScene("1"));
    EXPECT_EQ(runOpalRender(dir, "'" + (dir / "scene.usda").string() + "'").exitCode, 2);  // no -o
    EXPECT_EQ(runOpalRender(dir, "'" + (dir / "scene.usda").string() + "' -o x.exr --aov beauty").exitCode, 2);
    EXPECT_EQ(runOpalRender(dir, "'" + (dir / "scene.usda").string() + "' -o x.exr --resolution 0x5").exitCode, 2);
    EXPECT_EQ(runOpalRender(dir, "'" + (dir / "scene.usda").string() + "' -o x.exr --material jade").exitCode, 2);
    EXPECT_FALSE(std::filesystem::exists("x.exr"));
}

// --list-delegates, from the build tree: the delegate plugin next to opal-render, as its
// manifest (delegate/CMakeLists.txt) declares it, and nothing skipped.
TEST(OpalRender, ListDelegatesShowsTheDelegateItWouldLoad) {
    const test::SceneDir dir;
    unsetenv("OPAL_PLUGINPATH");
    const ProcessResult run = runOpalRender(dir, "--list-delegates");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::string plugins = std::filesystem::path(OPAL_BINARY_DIR "/lib/opal/plugins").lexically_normal().string();
    const std::string expected = "  OpalRendererPlugin\n    display name: Opal\n    priority: 100\n    library: " +
                                 plugins + "/opalDelegate/opalDelegate.so\n    manifest: " + plugins +
                                 "/opalDelegate/plugInfo.json\n";
    EXPECT_NE(run.out.find(expected), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("skipped: none"), std::string::npos) << run.out;
}

// A broken manifest on $OPAL_PLUGINPATH is listed as skipped with the reason (file:line:
// column), and a missing search path too; the shipped delegate is still found.
TEST(OpalRender, ListDelegatesShowsSkippedManifestsAndWhy) {
    const test::SceneDir dir;
    std::filesystem::create_directories(dir / "broken");
    dir.write("broken/plugInfo.json", "{\n    \"Plugins\": [\n");
    const std::string path = (dir / "broken").string() + ":" + (dir / "missing").string();
    setenv("OPAL_PLUGINPATH", path.c_str(), 1);
    const ProcessResult run = runOpalRender(dir, "--list-delegates");
    unsetenv("OPAL_PLUGINPATH");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::size_t skipped = run.out.find("skipped:\n");
    ASSERT_NE(skipped, std::string::npos) << run.out;
    EXPECT_NE(run.out.find("  " + (dir / "broken/plugInfo.json").string() + ":3:1: JSON syntax error", skipped),
              std::string::npos)
        << run.out;
    EXPECT_NE(run.out.find("  " + (dir / "missing").string() + ": plugin search path does not exist", skipped),
              std::string::npos)
        << run.out;
    EXPECT_LT(run.out.find("  OpalRendererPlugin\n"), skipped) << run.out;
}

}  // namespace
}  // namespace opal::scene
