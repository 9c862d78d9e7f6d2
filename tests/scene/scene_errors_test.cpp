// Every scene-level error yields file:line:column, the prim and the property at fault and
// what was expected. Each case is a whole scene; positions were counted by hand (lines
// from 1 at "#usda 1.0", columns from 1, 4-space indentation puts properties at column 5).
#include "examples/scene/material_override.h"
#include "examples/scene/render_setup.h"
#include "examples/scene/scene_reader.h"
#include "tests/scene/scene_test_files.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace opal::scene {
namespace {

struct ErrorCase {
    const char* name;
    std::string scene;     // the text of scene.usda
    std::string expected;  // how the message starts, after "<dir>/scene.usda"
    bool atSetup = false;  // the error comes when choosing the camera, not when reading
};

const std::string H = "#usda 1.0\n";
// A prim `type` "P" whose body (from line 4) is `body`.
std::string prim(const std::string& type, const std::string& body) {
    return H + "def " + type + " \"P\"\n{\n" + body + "}\n";
}
const std::string Camera = "def Camera \"Cam\"\n{\n}\n";

std::vector<ErrorCase> errorCases() {
    return {
        {"UnknownPrimType", H + "def Cube \"Box\"\n{\n}\n",
         ":2:1: Cube </Box>: unsupported prim type 'Cube' (Opal's scene subset: Xform, Scope"},
        {"UnknownAttribute", prim("SphereLight", "    float inputs:radiuss = 1\n"),
         ":4:5: SphereLight </P>: unknown attribute 'inputs:radiuss' (SphereLight accepts "},
        {"UnknownRelationship", prim("Xform", "    rel proxyPrim = </P>\n"),
         ":4:5: Xform </P>: unknown relationship 'proxyPrim' (Xform accepts "},
        {"WrongType", prim("SphereLight", "    double inputs:intensity = 5\n"),
         ":4:5: SphereLight </P>: attribute 'inputs:intensity' has type double, expected float"},
        {"NegativeIntensity", prim("SphereLight", "    float inputs:intensity = -2\n"),
         ":4:5: SphereLight </P>: attribute 'inputs:intensity' is -2, expected a value >= 0"},
        {"NegativeColor", prim("DistantLight", "    color3f inputs:color = (1, -0.5, 1)\n"),
         ":4:5: DistantLight </P>: attribute 'inputs:color' is (1, -0.5, 1), expected every component >= 0"},
        {"ConeAngleOutOfRange", prim("SphereLight", "    float inputs:shaping:cone:angle = 200\n"),
         ":4:5: SphereLight </P>: attribute 'inputs:shaping:cone:angle' is 200, expected a value in [0, 180]"},
        {"ColorTemperatureOutOfRange", prim("SphereLight", "    float inputs:colorTemperature = 100\n"),
         ":4:5: SphereLight </P>: attribute 'inputs:colorTemperature' is 100, expected a value in [500, 40000]"},
        {"LightMultiplier", prim("SphereLight", "    float inputs:diffuse = 0.5\n"),
         ":4:5: SphereLight </P>: attribute 'inputs:diffuse' differs from its fallback value, the only one Opal "
         "supports (per-light diffuse multipliers are not implemented)"},
        {"MissingReferenceFile", H + "def \"Candle\" (\n    references = @./missing.usda@\n)\n{\n}\n",
         ":3:18: prim </Candle>: references @./missing.usda@, which does not exist (resolved to "},
        {"BrokenReferencedAsset", H + "def \"Candle\" (\n    references = @./broken.usda@\n)\n{\n}\n",
         ":3:18: prim </Candle>: cannot load the asset @./broken.usda@: "},
        {"ReferenceOnXform", H + "def Xform \"Candle\" (\n    references = @./missing.usda@\n)\n{\n}\n",
         ":2:1: Xform </Candle>: references an asset, but its stronger type 'Xform' would replace the asset's Mesh"},
        {"MeshWithoutReference", prim("Mesh", ""),
         ":2:1: Mesh </P>: is a Mesh without a reference: Opal renders baked translucent assets"},
        {"OverPrim", H + "over \"P\"\n{\n}\n", ":2:1: over </P>: no layer of the scene's stack defines this prim"},
        {"UnsupportedApiSchema", H + "def Xform \"P\" (\n    prepend apiSchemas = [\"GeomModelAPI\"]\n)\n{\n}\n",
         ":2:1: Xform </P>: applies 'GeomModelAPI', which Opal's scene subset does not support on this prim type"},
        {"BadUpAxis", "#usda 1.0\n(\n    upAxis = \"X\"\n)\n", ":3:14: upAxis is 'X', expected \"Y\" or \"Z\""},
        {"NonPositiveMetersPerUnit", "#usda 1.0\n(\n    metersPerUnit = 0\n)\n",
         ":3:21: metersPerUnit is 0, expected a positive number"},
        {"BadResolution", prim("RenderSettings", "    uniform int2 resolution = (0, 480)\n"),
         ":4:5: RenderSettings </P>: attribute 'resolution' is (0, 480), expected each side in [1, 16384]"},
        {"HugeResolution", prim("RenderSettings", "    uniform int2 resolution = (640, 20000)\n"),
         ":4:5: RenderSettings </P>: attribute 'resolution' is (640, 20000), expected each side in [1, 16384]"},
        {"RenderSettingOfOtherType", prim("RenderSettings", "    float3 opal:tint = (1, 1, 1)\n"),
         ":4:5: RenderSettings </P>: attribute 'opal:tint' has type float3; render settings are bool, int, float"},
        {"SecondRenderSettings", H + "def RenderSettings \"A\"\n{\n}\ndef RenderSettings \"B\"\n{\n}\n",
         ":5:1: RenderSettings </B>: is a second RenderSettings prim (the first is </A> at "},
        {"RenderCameraMissing", prim("RenderSettings", "    rel camera = </Nope>\n") + Camera,
         ":4:5: RenderSettings </P>: relationship 'camera' targets </Nope>, which is not a Camera prim of the scene"},
        {"NoCamera", H + "def Xform \"World\"\n{\n}\n", ": the scene has no Camera prim to render through", true},
        {"SeveralCameras", H + Camera + "def Camera \"Other\"\n{\n}\n",
         ": the scene has several cameras (</Cam>, </Other>): choose one with --camera", true},
        {"BadClippingRange", prim("Camera", "    float2 clippingRange = (10, 1)\n"),
         ":4:5: Camera </P>: attribute 'clippingRange' is (10, 1), expected (near, far) with 0 < near < far"},
        {"NonPositiveFocalLength", prim("Camera", "    float focalLength = 0\n"),
         ":4:5: Camera </P>: attribute 'focalLength' is 0, expected a value > 0"},
        {"OrthographicCamera", prim("Camera", "    token projection = \"orthographic\"\n"),
         ":4:5: Camera </P>: attribute 'projection' differs from its fallback value, the only one Opal supports "
         "(orthographic cameras are not implemented)"},
        {"BindingToMissingMaterial", prim("Xform", "    rel material:binding = </Looks/Wax>\n"),
         ":4:5: Xform </P>: relationship 'material:binding' targets </Looks/Wax>, which is not a Material prim"},
        {"BindingToPropertyPath", prim("Xform", "    rel material:binding = </Looks/Wax.outputs:surface>\n"),
         ":4:5: Xform </P>: relationship 'material:binding' </Looks/Wax.outputs:surface> is a property path"},
        {"UnknownPreset", prim("Material", "    token opal:preset = \"jade\"\n"),
         ":4:5: Material </P>: attribute 'opal:preset' is 'jade', which is not a preset (marble, skin1, skin2, "},
        {"MaterialWithoutCoefficients", prim("Material", "    bool opal:specular = 0\n"),
         ":2:1: Material </P>: sets no subsurface coefficients: author opal:preset, "},
        {"TwoParameterizations",
         prim("Material", "    token opal:preset = \"marble\"\n    color3f opal:albedo = (0.5, 0.5, 0.5)\n"
                          "    color3f opal:meanFreePath = (1, 1, 1)\n"),
         ":5:5: Material </P>: attribute 'opal:albedo' conflicts with 'opal:preset' (at "},
        {"HalfAPair", prim("Material", "    color3f opal:sigmaA = (0.1, 0.1, 0.1)\n"),
         ":4:5: Material </P>: attribute 'opal:sigmaA' needs the rest of opal:sigmaSPrime + opal:sigmaA"},
        {"AlbedoOutOfRange",
         prim("Material", "    color3f opal:albedo = (0.5, 1.5, 0.5)\n    color3f opal:meanFreePath = (1, 1, 1)\n"),
         ":4:5: Material </P>: attribute 'opal:albedo' is (0.5, 1.5, 0.5), expected every component in (0, 1)"},
        {"EtaBelowOne", prim("Material", "    token opal:preset = \"marble\"\n    float opal:eta = 0.9\n"),
         ":5:5: Material </P>: attribute 'opal:eta' is 0.9, expected a value in [1, 3]"},
        {"EtaAboveTheDipolesRange", prim("Material", "    token opal:preset = \"marble\"\n    float opal:eta = 3.9\n"),
         ":5:5: Material </P>: attribute 'opal:eta' is 3.9, expected a value in [1, 3]"},
        {"EtaHalf", prim("Material", "    token opal:preset = \"marble\"\n    float opal:eta = 0.5\n"),
         ":5:5: Material </P>: attribute 'opal:eta' is 0.5, expected a value in [1, 3]"},
        {"EtaFarAboveTheDipolesRange", prim("Material", "    token opal:preset = \"marble\"\n    float opal:eta = 10\n"),
         ":5:5: Material </P>: attribute 'opal:eta' is 10, expected a value in [1, 3]"},
        {"RoughnessOutOfRange", prim("Material", "    token opal:preset = \"marble\"\n    float opal:specularRoughness = 2\n"),
         ":5:5: Material </P>: attribute 'opal:specularRoughness' is 2, expected a value in [0, 1]"},
        {"TransformOnMaterial",
         prim("Material", "    token opal:preset = \"marble\"\n    double3 xformOp:translate = (1, 0, 0)\n"),
         ":5:5: Material </P>: 'xformOp:translate': this prim type has no transformation (use an Xform)"},
        {"MissingDomeTexture", prim("DomeLight", "    asset inputs:texture:file = @./sky.hdr@\n"),
         ":4:5: DomeLight </P>: attribute 'inputs:texture:file' names @./sky.hdr@, which does not exist (resolved to "},
        {"DomeTextureFormat", prim("DomeLight", "    token inputs:texture:format = \"angular\"\n"),
         ":4:5: DomeLight </P>: attribute 'inputs:texture:format' is 'angular'; Opal reads lat-long images only"},
        {"ShadowFieldWithoutField", prim("OpalShadowFieldLight", ""),
         ":2:1: OpalShadowFieldLight </P>: needs opal:field, the light asset holding its shadow field"},
        {"BadVisibility", prim("Xform", "    token visibility = \"hidden\"\n"),
         ":4:5: Xform </P>: attribute 'visibility' is 'hidden', expected \"inherited\" or \"invisible\""},
        {"SyntaxErrorFromTheReader", prim("Xform", "    float x = \n"), ":5:1: unexpected '}', expected a number"},
    };
}

class SceneErrors : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(SceneErrors, MessageStartsWithFileLineColumn) {
    const ErrorCase& c = GetParam();
    const test::SceneDir dir;
    dir.write("broken.usda", "#usda 1.0\n");
    const std::filesystem::path file = dir.write("scene.usda", c.scene);
    std::string message = "no error";
    try {
        AssetCache assets;
        const Scene scene = readScene(file, assets);
        if (c.atSetup) chooseRenderSetup(scene, {});
    } catch (const Error& e) {
        message = e.what();
    }
    const std::string expected = file.string() + c.expected;
    EXPECT_EQ(message.substr(0, expected.size()), expected) << "full message: " << message;
}

INSTANTIATE_TEST_SUITE_P(Table, SceneErrors, ::testing::ValuesIn(errorCases()),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(SceneSetupErrors, RequestedCameraMustExist) {
    const test::SceneDir dir;
    const std::filesystem::path file = dir.write("scene.usda", H + Camera);
    AssetCache assets;
    const Scene scene = readScene(file, assets);
    try {
        chooseRenderSetup(scene, {hd::SdfPath("/World/Cam"), std::nullopt});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  file.string() + ": --camera </World/Cam> is not a Camera prim of the scene (cameras: </Cam>)");
    }
}

TEST(SceneSetupErrors, ResolutionText) {
    EXPECT_EQ(parseResolution("1920x1080"), (Resolution{1920, 1080}));
    for (const char* bad : {"1920", "x1080", "1920x", "0x10", "10x-1", "1920x1080x3", "axb", "20000x10"})
        EXPECT_THROW(parseResolution(bad), Error) << bad;
}

TEST(SceneSetupErrors, UnknownOverridePreset) {
    Scene scene;
    EXPECT_THROW(overrideMaterials(scene, "jade"), Error);
}

}  // namespace
}  // namespace opal::scene
