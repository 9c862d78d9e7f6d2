// A small scene read from disk answers the right descriptions: meshes (one asset loaded
// once, transforms composed with parents, bindings inherited), materials (preset,
// coefficients, artist parameters), lights with UsdLux fallbacks, the camera and the
// render settings; the scene source populates a render index whose prims pull exactly
// these; the material override rebinds every mesh.
#include "examples/scene/material_override.h"
#include "examples/scene/render_setup.h"
#include "examples/scene/scene_reader.h"
#include "examples/scene/usda_scene_source.h"
#include "tests/scene/scene_test_files.h"

#include "schema/asset/shadow_field_layer.h"

#include <gtest/gtest.h>

#include <cmath>

namespace opal::scene {
namespace {

const char* const SmallScene = R"(#usda 1.0
(
    metersPerUnit = 0.001
    upAxis = "Y"
)

def Xform "World"
{
    double3 xformOp:translate = (10, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]

    def "Candle" (
        prepend apiSchemas = ["MaterialBindingAPI"]
        references = @./sphere.usda@
    )
    {
        rel material:binding = </Looks/Wax>
        float xformOp:rotateY = 90
        uniform token[] xformOpOrder = ["xformOp:rotateY"]
    }

    def Xform "Shelf" (
        prepend apiSchemas = ["MaterialBindingAPI"]
    )
    {
        rel material:binding = <../../Looks/Jade>
        def Mesh "Second" (
            references = @./sphere.usda@</testSphere>
        )
        {
            float3[] extent = [(-5, -5, -5), (5, 5, 5)]
        }
        def "Hidden" (
            references = @./sphere.usda@
        )
        {
            token visibility = "invisible"
        }
    }
}

def Scope "Looks"
{
    def Material "Wax"
    {
        token opal:preset = "marble"
        bool opal:specular = 0
    }
    def Material "Jade"
    {
        color3f opal:albedo = (0.6, 0.8, 0.7)
        color3f opal:meanFreePath = (2, 4, 3)
        float opal:eta = 1.5
        float opal:specularRoughness = 0.2
    }
    def Material "Coefficients"
    {
        color3f opal:sigmaSPrime = (1, 2, 3)
        color3f opal:sigmaA = (0.1, 0.2, 0.3)
    }
}

def Xform "Lights"
{
    def SphereLight "Flame" (
        prepend apiSchemas = ["ShapingAPI"]
    )
    {
        float inputs:intensity = 20
        float inputs:exposure = 1
        color3f inputs:color = (1, 0.6, 0.3)
        bool inputs:normalize = 1
        float inputs:radius = 0.25
        bool treatAsPoint = 1
        float shaping:cone:angle = 45
        float inputs:shaping:cone:softness = 0.5
        float inputs:diffuse = 1
        double3 xformOp:translate = (0, 20, 0)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def DistantLight "Sun"
    {
        float inputs:angle = 1
        bool inputs:enableColorTemperature = 1
        float inputs:colorTemperature = 2700
    }
    def DomeLight "Sky"
    {
        asset inputs:texture:file = @./sky.hdr@ (
            colorSpace = "ACEScg"
        )
        token inputs:texture:format = "latlong"
        float inputs:intensity = 0.1
    }
}

def Camera "Camera"
{
    float focalLength = 35
    float horizontalAperture = 36
    float verticalAperture = 24
    float2 clippingRange = (0.5, 500)
    double3 xformOp:translate = (0, 0, 40)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}

def RenderSettings "Settings"
{
    uniform int2 resolution = (320, 240)
    rel camera = </Camera>
    bool opal:reference = 1
    int opal:tileSize = 16
}
)";


void expectNear(const Imath::V3d& a, const Imath::V3d& b) {
    EXPECT_NEAR(a.x, b.x, 1e-9);
    EXPECT_NEAR(a.y, b.y, 1e-9);
    EXPECT_NEAR(a.z, b.z, 1e-9);
}

void expectRgb(const Rgb& a, const Rgb& b, double tolerance = 1e-6) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], tolerance) << "channel " << c;
}

class SmallSceneTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir.writeSphereAsset("sphere");
        dir.write("sky.hdr", "a texture is only resolved here, never read");
        scene = readScene(dir.write("scene.usda", SmallScene), assets);
    }
    test::SceneDir dir;
    AssetCache assets;
    Scene scene;
};

TEST_F(SmallSceneTest, LayerMetadata) {
    EXPECT_EQ(scene.upAxis, "Y");
    EXPECT_EQ(scene.metersPerUnit, 0.001);
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();  // the asset is in mm too
}

TEST_F(SmallSceneTest, MeshesShareOneLoadedAsset) {
    ASSERT_EQ(scene.meshes.size(), 3u);
    const hd::MeshDesc& candle = scene.meshes.at("/World/Candle").desc;
    EXPECT_EQ(assets.reads(), 1u);
    EXPECT_EQ(candle.asset->name, "testSphere");
    EXPECT_EQ(scene.meshes.at("/World/Shelf/Second").desc.asset, candle.asset);
    EXPECT_EQ(scene.meshes.at("/World/Candle").assetFile, dir / "sphere.usda");
}

TEST_F(SmallSceneTest, MeshTransformsComposeWithTheParent) {
    // rotateY 90 in the candle, then the world's translate (10, 0, 0): (1,0,0) -> (0,0,-1) -> (10,0,-1).
    expectNear(Imath::V3d(1, 0, 0) * scene.meshes.at("/World/Candle").desc.transform, {10, 0, -1});
    expectNear(Imath::V3d(1, 2, 3) * scene.meshes.at("/World/Shelf/Second").desc.transform, {11, 2, 3});
}

TEST_F(SmallSceneTest, BindingsAndVisibilityInherit) {
    EXPECT_EQ(scene.meshes.at("/World/Candle").desc.material, "/Looks/Wax");
    EXPECT_EQ(scene.meshes.at("/World/Shelf/Second").desc.material, "/Looks/Jade");  // relative target
    EXPECT_EQ(scene.meshes.at("/World/Shelf/Hidden").desc.material, "/Looks/Jade");
    EXPECT_TRUE(scene.meshes.at("/World/Candle").desc.visible);
    EXPECT_FALSE(scene.meshes.at("/World/Shelf/Hidden").desc.visible);
}

TEST_F(SmallSceneTest, PresetMaterial) {
    const hd::MaterialDesc& wax = scene.materials.at("/Looks/Wax").desc;
    // Jensen et al. 2001, Table 2, marble: sigma_s' = (2.19, 2.62, 3.00), sigma_a = (0.0021, 0.0041, 0.0071) mm^-1.
    expectRgb(wax.subsurface.sigmaSPrime, {2.19, 2.62, 3.00});
    expectRgb(wax.subsurface.sigmaA, {0.0021, 0.0041, 0.0071});
    EXPECT_FALSE(wax.specular);
    EXPECT_DOUBLE_EQ(wax.specularRoughness, hd::MaterialDesc{}.specularRoughness);
}

TEST_F(SmallSceneTest, ArtistMaterialReproducesItsParameters) {
    const hd::MaterialDesc& jade = scene.materials.at("/Looks/Jade").desc;
    // The forward closed form of the inverted coefficients gives the authored values back.
    const ArtistMaterial back = toArtist(jade.subsurface);
    expectRgb(back.albedo, {0.6, 0.8, 0.7}, 1e-4);
    expectRgb(back.meanFreePath, {2, 4, 3}, 1e-3);
    EXPECT_DOUBLE_EQ(jade.subsurface.eta, 1.5);
    EXPECT_NEAR(jade.specularRoughness, 0.2, 1e-7);
    EXPECT_TRUE(jade.specular);
}

TEST_F(SmallSceneTest, CoefficientMaterial) {
    const Material& m = scene.materials.at("/Looks/Coefficients").desc.subsurface;
    expectRgb(m.sigmaSPrime, {1, 2, 3});
    expectRgb(m.sigmaA, {0.1, 0.2, 0.3});
    EXPECT_DOUBLE_EQ(m.eta, Material{}.eta);
}

TEST_F(SmallSceneTest, SphereLightParameters) {
    const SceneLight& flame = scene.lights.at("/Lights/Flame");
    EXPECT_EQ(flame.primType, hd::PrimType::SphereLight);
    EXPECT_EQ(flame.desc.kind, hd::LightKind::Sphere);
    EXPECT_DOUBLE_EQ(flame.desc.intensity, 20);
    EXPECT_DOUBLE_EQ(flame.desc.exposure, 1);
    expectRgb(flame.desc.color, {1, 0.6, 0.3});
    EXPECT_TRUE(flame.desc.normalize);
    EXPECT_DOUBLE_EQ(flame.desc.radius, 0.25);
    EXPECT_TRUE(flame.desc.treatAsPoint);
    EXPECT_EQ(flame.desc.shapingConeAngle, 45.0);
    EXPECT_DOUBLE_EQ(flame.desc.shapingConeSoftness, 0.5);
    expectNear(Imath::V3d(0, 0, 0) * flame.desc.transform, {0, 20, 0});
}

TEST_F(SmallSceneTest, DistantLightFallsBackToUsdLuxIntensity) {
    const SceneLight& sun = scene.lights.at("/Lights/Sun");
    EXPECT_EQ(sun.primType, hd::PrimType::DistantLight);
    EXPECT_DOUBLE_EQ(sun.desc.intensity, 50000);
    EXPECT_DOUBLE_EQ(sun.desc.angle, 1);
    expectRgb(sun.desc.color, {1, 1, 1});
    EXPECT_TRUE(sun.desc.enableColorTemperature);
    EXPECT_DOUBLE_EQ(sun.desc.colorTemperature, 2700);
    EXPECT_FALSE(scene.lights.at("/Lights/Flame").desc.enableColorTemperature);
}

TEST_F(SmallSceneTest, DomeLightTextureIsAnchoredAtTheScene) {
    const SceneLight& sky = scene.lights.at("/Lights/Sky");
    EXPECT_EQ(sky.primType, hd::PrimType::DomeLight);
    EXPECT_EQ(sky.desc.textureFile, (dir / "sky.hdr").string());
    EXPECT_EQ(sky.desc.textureColorSpace, "ACEScg");
    EXPECT_NEAR(sky.desc.intensity, 0.1, 1e-7);
}

TEST_F(SmallSceneTest, Camera) {
    const hd::CameraDesc& camera = scene.cameras.at("/Camera").desc;
    EXPECT_DOUBLE_EQ(camera.focalLength, 35);
    EXPECT_DOUBLE_EQ(camera.horizontalAperture, 36);
    EXPECT_DOUBLE_EQ(camera.verticalAperture, 24);
    EXPECT_DOUBLE_EQ(camera.nearClip, 0.5);
    EXPECT_DOUBLE_EQ(camera.farClip, 500);
    expectNear(Imath::V3d(0, 0, 0) * camera.transform, {0, 0, 40});
}

TEST_F(SmallSceneTest, RenderSettingsAndSetup) {
    ASSERT_TRUE(scene.renderSettings);
    const SceneRenderSettings& settings = *scene.renderSettings;
    EXPECT_EQ(settings.resolution, (Resolution{320, 240}));
    EXPECT_EQ(settings.camera, "/Camera");
    ASSERT_EQ(settings.delegateSettings.size(), 2u);
    EXPECT_EQ(settings.delegateSettings[0].name, "opal:reference");
    EXPECT_EQ(settings.delegateSettings[0].value, hd::Value(true));
    EXPECT_EQ(settings.delegateSettings[1].name, "opal:tileSize");
    EXPECT_EQ(settings.delegateSettings[1].value, hd::Value(16));

    const RenderSetup setup = chooseRenderSetup(scene, {});
    EXPECT_EQ(setup.camera, "/Camera");
    EXPECT_EQ(setup.resolution, (Resolution{320, 240}));
    EXPECT_EQ(chooseRenderSetup(scene, {std::nullopt, Resolution{64, 32}}).resolution, (Resolution{64, 32}));
}

TEST_F(SmallSceneTest, MaterialOverrideRebindsEveryMesh) {
    overrideMaterials(scene, "ketchup");
    for (const auto& [path, mesh] : scene.meshes) EXPECT_EQ(mesh.desc.material, OverrideMaterialPath) << path;
    const hd::MaterialDesc& ketchup = scene.materials.at(OverrideMaterialPath).desc;
    // Jensen et al. 2001, ketchup: sigma_s' = (0.18, 0.07, 0.03), sigma_a = (0.061, 0.97, 1.45) mm^-1.
    expectRgb(ketchup.subsurface.sigmaSPrime, {0.18, 0.07, 0.03});
    expectRgb(ketchup.subsurface.sigmaA, {0.061, 0.97, 1.45});
    EXPECT_TRUE(ketchup.specular);
}

TEST(SceneDefaults, ResolutionFollowsTheCameraAperture) {
    const test::SceneDir dir;
    AssetCache assets;
    const Scene scene = readScene(dir.write("scene.usda", "#usda 1.0\ndef Camera \"C\"\n{\n}\n"), assets);
    const hd::CameraDesc& camera = scene.cameras.at("/C").desc;
    // UsdGeomCamera's fallbacks.
    EXPECT_DOUBLE_EQ(camera.focalLength, 50);
    EXPECT_NEAR(camera.horizontalAperture, 20.955, 1e-6);
    EXPECT_NEAR(camera.verticalAperture, 15.2908, 1e-6);
    EXPECT_DOUBLE_EQ(camera.nearClip, 1);
    EXPECT_DOUBLE_EQ(camera.farClip, 1000000);
    // 640 x 640 * 15.2908 / 20.955 = 466.99.
    EXPECT_EQ(chooseRenderSetup(scene, {}).resolution, (Resolution{640, 467}));
}

// A layer stores these as floats, so a value saved at its default (the viewer writes every
// parameter) must read back as the unauthored default, bit for bit: else the saved scene
// renders a float step away from the picture it was saved from.
TEST(SceneDefaults, AnAttributeAuthoredAtItsDefaultReadsAsTheUnauthoredOne) {
    const test::SceneDir dir;
    AssetCache assets;
    const Scene scene = readScene(dir.write("scene.usda", R"(#usda 1.0
def Material "Plain"
{
    token opal:preset = "marble"
}
def Material "Authored"
{
    token opal:preset = "marble"
    float opal:specularRoughness = 0.35
}
def DistantLight "PlainSun"
{
}
def DistantLight "AuthoredSun"
{
    float inputs:angle = 0.53
}
)"),
                                  assets);
    EXPECT_EQ(scene.materials.at("/Plain").desc.specularRoughness, scene.materials.at("/Authored").desc.specularRoughness);
    EXPECT_EQ(scene.lights.at("/PlainSun").desc.angle, scene.lights.at("/AuthoredSun").desc.angle);
    EXPECT_EQ(hd::CameraDesc{}.nearClip, double(float(hd::CameraDesc{}.nearClip)));
}

TEST(SceneDefaults, UnitMismatchWarns) {
    const test::SceneDir dir;
    dir.writeSphereAsset("sphere");
    AssetCache assets;
    const Scene scene = readScene(
        dir.write("scene.usda", "#usda 1.0\n(\n    metersPerUnit = 0.01\n)\ndef \"S\" (\n    references = "
                                "@./sphere.usda@\n)\n{\n}\n"),
        assets);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_EQ(scene.warnings[0].substr(0, scene.file.string().size() + 5), scene.file.string() + ":5:1:");
    EXPECT_NE(scene.warnings[0].find("metersPerUnit 0.01"), std::string::npos) << scene.warnings[0];
}

TEST(SceneDefaults, StrongerAncestorBindingWins) {
    const test::SceneDir dir;
    dir.writeSphereAsset("sphere");
    AssetCache assets;
    const Scene scene = readScene(dir.write("scene.usda", R"(#usda 1.0
def Xform "World"
{
    rel material:binding = </Looks/Strong> (
        bindMaterialAs = "strongerThanDescendants"
    )
    def "A" (
        references = @./sphere.usda@
    )
    {
        rel material:binding = </Looks/Weak>
    }
}
def Xform "Other"
{
    rel material:binding = </Looks/Strong>
    def "B" (
        references = @./sphere.usda@
    )
    {
        rel material:binding = </Looks/Weak>
    }
}
def Scope "Looks"
{
    def Material "Strong"
    {
        token opal:preset = "skin1"
    }
    def Material "Weak"
    {
        token opal:preset = "skin2"
    }
}
)"),
                                  assets);
    EXPECT_EQ(scene.meshes.at("/World/A").desc.material, "/Looks/Strong");
    EXPECT_EQ(scene.meshes.at("/Other/B").desc.material, "/Looks/Weak");  // the nearer binding
}

TEST(SceneDefaults, InvisibleLightsAreLeftOut) {
    const test::SceneDir dir;
    AssetCache assets;
    const Scene scene = readScene(dir.write("scene.usda", R"(#usda 1.0
def Xform "Off"
{
    token visibility = "invisible"
    def SphereLight "Hidden"
    {
    }
}
def SphereLight "On"
{
}
)"),
                                  assets);
    EXPECT_EQ(scene.lights.size(), 1u);
    EXPECT_TRUE(scene.lights.count("/On"));
}

TEST(SceneDefaults, ClassAndInactivePrimsAreSkipped) {
    const test::SceneDir dir;
    AssetCache assets;
    const Scene scene = readScene(dir.write("scene.usda", "#usda 1.0\nclass Cube \"Template\"\n{\n}\n"
                                                          "def Camera \"Off\" (\n    active = false\n)\n{\n}\n"),
                                  assets);
    EXPECT_TRUE(scene.cameras.empty());
}

// A render delegate whose prims pull their description in sync and keep it: what a
// renderer sees of the scene source.
template <class Desc>
class PullingPrim : public hd::Sprim {
public:
    using Pull = Desc (hd::SceneDelegate::*)(const hd::SdfPath&) const;
    PullingPrim(const hd::SdfPath& id, Pull pull) : hd::Sprim(id), pull_(pull) {}
    void sync(const hd::SceneDelegate& scene, hd::DirtyBits* bits) override {
        desc = (scene.*pull_)(id());
        *bits = hd::Dirty::Clean;
    }
    hd::DirtyBits initialDirtyBits() const override { return hd::Dirty::AllDirty; }
    Desc desc;

private:
    Pull pull_;
};

class PullingMesh : public hd::Rprim {
public:
    using hd::Rprim::Rprim;
    void sync(const hd::SceneDelegate& scene, hd::DirtyBits* bits) override {
        desc = scene.mesh(id());
        *bits = hd::Dirty::Clean;
    }
    hd::DirtyBits initialDirtyBits() const override { return hd::Dirty::AllDirty; }
    hd::MeshDesc desc;
};

class PullingDelegate : public hd::RenderDelegate {
public:
    std::vector<hd::Token> supportedRprimTypes() const override { return {hd::PrimType::TranslucentMesh}; }
    std::vector<hd::Token> supportedSprimTypes() const override {
        return {hd::PrimType::Camera, hd::PrimType::Material, hd::PrimType::SphereLight, hd::PrimType::DistantLight,
                hd::PrimType::DomeLight};
    }
    std::vector<hd::Token> supportedBprimTypes() const override { return {}; }
    std::unique_ptr<hd::Rprim> createRprim(const hd::Token& type, const hd::SdfPath& id) override {
        return type == hd::PrimType::TranslucentMesh ? std::make_unique<PullingMesh>(id) : nullptr;
    }
    std::unique_ptr<hd::Sprim> createSprim(const hd::Token& type, const hd::SdfPath& id) override {
        if (type == hd::PrimType::Camera) return std::make_unique<PullingPrim<hd::CameraDesc>>(id, &hd::SceneDelegate::camera);
        if (type == hd::PrimType::Material)
            return std::make_unique<PullingPrim<hd::MaterialDesc>>(id, &hd::SceneDelegate::material);
        if (type == hd::PrimType::ShadowFieldLight) return nullptr;
        return std::make_unique<PullingPrim<hd::LightDesc>>(id, &hd::SceneDelegate::light);
    }
    std::unique_ptr<hd::Bprim> createBprim(const hd::Token&, const hd::SdfPath&) override { return nullptr; }
    void setRenderSetting(const hd::Token&, const hd::Value&) override {}
    hd::Value renderSetting(const hd::Token&) const override { return {}; }
    std::map<hd::Token, hd::Value> renderSettings() const override { return {}; }
    std::vector<hd::RenderSettingDescriptor> renderSettingDescriptors() const override { return {}; }
    std::map<hd::Token, hd::Value> renderStats() const override { return {}; }
    std::vector<hd::AovDescriptor> aovDescriptors() const override { return {}; }
    std::unique_ptr<hd::RenderPass> createRenderPass(hd::RenderIndex&) override { return nullptr; }
    void commitResources(hd::RenderIndex&) override {}
};

TEST_F(SmallSceneTest, PopulatedPrimsPullTheSceneDescriptions) {
    const UsdaSceneSource source(scene);
    PullingDelegate delegate;
    hd::RenderIndex index(delegate);
    source.populate(index);
    index.sync();
    EXPECT_EQ(index.typeOf("/World/Candle"), hd::PrimType::TranslucentMesh);
    EXPECT_EQ(index.typeOf("/Looks/Jade"), hd::PrimType::Material);
    EXPECT_EQ(index.typeOf("/Lights/Sky"), hd::PrimType::DomeLight);
    EXPECT_EQ(index.typeOf("/Camera"), hd::PrimType::Camera);
    const auto& candle = static_cast<const PullingMesh&>(*index.rprim("/World/Candle"));
    EXPECT_EQ(candle.desc.material, "/Looks/Wax");
    EXPECT_EQ(candle.desc.asset, scene.meshes.at("/World/Candle").desc.asset);
    const auto& flame = static_cast<const PullingPrim<hd::LightDesc>&>(*index.sprim("/Lights/Flame"));
    EXPECT_DOUBLE_EQ(flame.desc.intensity, 20);
    const auto& camera = static_cast<const PullingPrim<hd::CameraDesc>&>(*index.sprim("/Camera"));
    EXPECT_DOUBLE_EQ(camera.desc.focalLength, 35);
    EXPECT_THROW(source.mesh("/Nope"), Error);
    EXPECT_THROW(source.light("/Camera"), Error);
}

TEST(SceneSource, RefusedPrimNamesItsLocation) {
    const test::SceneDir dir;
    dir.write("flame.field", "only resolved here");
    AssetCache assets;
    const std::filesystem::path file = dir.write(
        "scene.usda", "#usda 1.0\ndef OpalShadowFieldLight \"Flame\"\n{\n    asset opal:field = @./flame.field@\n}\n");
    const UsdaSceneSource source(readScene(file, assets));
    EXPECT_EQ(source.light("/Flame").shadowField, (dir / "flame.field").string());
    PullingDelegate delegate;
    hd::RenderIndex index(delegate);
    try {
        source.populate(index);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), file.string() + ":2:1: </Flame>: render index: the render delegate does not "
                                                          "support prim type 'opalShadowFieldLight' (/Flame)");
    }
}

TEST(SceneSource, ShadowFieldFlickerIsReadAndTheTimeReachesTheLight) {
    const test::SceneDir dir;
    dir.write("flame.field", "only resolved here");
    AssetCache assets;
    const std::string light = "#usda 1.0\ndef OpalShadowFieldLight \"Flame\"\n{\n    asset opal:field = @./flame.field@\n";
    UsdaSceneSource source(readScene(
        dir.write("scene.usda", light + "    float opal:flicker:amplitude = 0.25\n    float opal:flicker:frequency = 5\n"
                                        "    int opal:flicker:seed = 7\n}\n"),
        assets));
    const hd::LightDesc flame = source.light("/Flame");
    EXPECT_DOUBLE_EQ(flame.flicker.amplitude, 0.25);
    EXPECT_DOUBLE_EQ(flame.flicker.frequency, 5.0);
    EXPECT_EQ(flame.flicker.seed, 7u);
    EXPECT_EQ(flame.time, 0.0);
    PullingDelegate delegate;
    hd::RenderIndex index(delegate);
    source.setTime(1.5, index, assets);
    EXPECT_EQ(source.light("/Flame").time, 1.5);
    EXPECT_THROW(source.setTime(std::nan(""), index, assets), Error);

    const std::filesystem::path bad =
        dir.write("bad.usda", light + "    float opal:flicker:amplitude = 2\n}\n");
    try {
        (void)readScene(bad, assets);
        FAIL() << "an amplitude of 2 was read";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(":5:5: OpalShadowFieldLight </Flame>: attribute 'opal:flicker:amplitude' "
                                             "is 2, expected a value in [0, 1]"),
                  std::string::npos)
            << e.what();
    }
}

// An animated light and a camera under an animated xform (USD time samples), a still
// mesh and a material with a single sample: the time-varying prims are named, read at the
// scene time (linear between samples, held at the ends), and only they are marked dirty
// and pulled again when the time moves; a host's edit to a still prim stays.
const char* const AnimatedScene = R"(#usda 1.0
(
    timeCodesPerSecond = 24
)

def "Ball" (
    references = @./sphere.usda@
)
{
}

def Material "Wax"
{
    token opal:preset = "marble"
    float opal:specularRoughness.timeSamples = {
        0: 0.25,
    }
}

def SphereLight "Key"
{
    float inputs:intensity = 99
    float inputs:intensity.timeSamples = {
        0: 10,
        48: 30,
    }
    color3f inputs:color.timeSamples = {
        24: (1, 0.5, 0),
    }
    double3 xformOp:translate.timeSamples = {
        0: (0, 0, 0),
        24: (24, -12, 0),
    }
    uniform token[] xformOpOrder = ["xformOp:translate"]
}

def Xform "Rig"
{
    float xformOp:rotateY.timeSamples = {
        0: 0,
        24: 90,
    }
    uniform token[] xformOpOrder = ["xformOp:rotateY"]

    def Camera "Camera"
    {
        double3 xformOp:translate = (0, 0, 40)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
}
)";

TEST(SceneSource, TimeSampledLightsCamerasAndXformsFollowTheSceneTime) {
    test::SceneDir dir;
    dir.writeSphereAsset("sphere");
    AssetCache assets;
    const std::filesystem::path file = dir.write("scene.usda", AnimatedScene);
    Scene scene = readScene(file, assets);
    EXPECT_EQ(scene.timeVarying, (std::set<hd::SdfPath>{"/Key", "/Rig/Camera"}));
    EXPECT_DOUBLE_EQ(scene.lights.at("/Key").desc.intensity, 10.0);
    EXPECT_DOUBLE_EQ(scene.materials.at("/Wax").desc.specularRoughness, 0.25);
    scene.materials.at("/Wax").desc.specularRoughness = 0.5;  // a host's edit of a still prim

    UsdaSceneSource source(std::move(scene));
    PullingDelegate delegate;
    hd::RenderIndex index(delegate);
    source.populate(index);
    index.sync();
    source.setTime(0.5, index, assets);  // time code 12
    EXPECT_EQ(index.changeTracker().dirtyBits("/Key"), hd::Dirty::Params | hd::Dirty::Transform);
    EXPECT_NE(index.changeTracker().dirtyBits("/Rig/Camera"), hd::Dirty::Clean);
    EXPECT_EQ(index.changeTracker().dirtyBits("/Ball"), hd::Dirty::Clean);
    EXPECT_EQ(index.changeTracker().dirtyBits("/Wax"), hd::Dirty::Clean);
    index.sync();

    const auto& key = static_cast<const PullingPrim<hd::LightDesc>&>(*index.sprim("/Key"));
    EXPECT_DOUBLE_EQ(key.desc.intensity, 15.0);              // 10 + (30 - 10) * 12 / 48
    expectRgb(key.desc.color, Rgb(1.0, 0.5, 0.0));           // one sample: held everywhere
    expectNear(Imath::V3d(0, 0, 0) * key.desc.transform, {12, -6, 0});
    const auto& camera = static_cast<const PullingPrim<hd::CameraDesc>&>(*index.sprim("/Rig/Camera"));
    const double a = 45.0 * M_PI / 180.0;                    // rotateY 45 at time code 12
    expectNear(Imath::V3d(0, 0, 0) * camera.desc.transform, {40 * std::sin(a), 0, 40 * std::cos(a)});
    EXPECT_DOUBLE_EQ(source.scene().materials.at("/Wax").desc.specularRoughness, 0.5);

    source.setTime(10.0, index, assets);  // time code 240: held at the last samples
    EXPECT_DOUBLE_EQ(source.light("/Key").intensity, 30.0);
    expectNear(Imath::V3d(0, 0, 0) * source.light("/Key").transform, {24, -12, 0});
}

TEST(SceneSource, AnimationOutsideLightsCamerasAndXformsIsRefusedWithItsLocation) {
    test::SceneDir dir;
    AssetCache assets;
    const std::string material =
        "#usda 1.0\ndef Material \"M\"\n{\n    float opal:eta.timeSamples = {\n        0: 1.3,\n        10: 1.5,\n    }\n}\n";
    const std::string visibility =
        "#usda 1.0\ndef Xform \"X\"\n{\n    token visibility.timeSamples = {\n        0: \"inherited\",\n"
        "        10: \"invisible\",\n    }\n}\n";
    const std::string late = "#usda 1.0\ndef SphereLight \"L\"\n{\n    float inputs:intensity.timeSamples = {\n"
                             "        0: 10,\n        10: -10,\n    }\n}\n";
    for (const auto& [text, message] : std::vector<std::pair<std::string, std::string>>{
             {material, ":4:5: Material </M>: attribute 'opal:eta' has timeSamples, which Opal reads on lights, "
                        "cameras and xformOps only"},
             {visibility, ":4:5: Xform </X>: attribute 'visibility' has timeSamples; animated visibility is not "
                          "supported"}}) {
        try {
            (void)readScene(dir.write("scene.usda", text), assets);
            FAIL() << text;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
        }
    }
    const std::filesystem::path file = dir.write("late.usda", late);
    EXPECT_DOUBLE_EQ(readScene(file, assets, 4.0).lights.at("/L").desc.intensity, 2.0);
    try {
        (void)readScene(file, assets, 9.0);  // -8 there
        FAIL() << "a negative intensity was read";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("late.usda:4:5: SphereLight </L>: attribute 'inputs:intensity'"),
                  std::string::npos)
            << e.what();
    }
}

TEST(SceneSource, ALightReferencesTheLayerOpalBakeLightWrote) {
    const test::SceneDir dir;
    dir.write("flame.0123456789abcdef.opal", "only resolved here");
    writeShadowFieldLayer(dir / "flame.usda", "flame", "./flame.0123456789abcdef.opal", 0x0123456789abcdefull);
    AssetCache assets;
    const UsdaSceneSource source(readScene(dir.write("scene.usda", R"(#usda 1.0
def OpalShadowFieldLight "Flame" (
    references = @./flame.usda@
)
{
    float inputs:intensity = 5
    double3 xformOp:translate = (0, 84, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
)"),
                                           assets));
    const hd::LightDesc flame = source.light("/Flame");
    EXPECT_EQ(flame.kind, hd::LightKind::ShadowField);
    EXPECT_EQ(flame.shadowField, (dir / "flame.0123456789abcdef.opal").string());
    EXPECT_DOUBLE_EQ(flame.intensity, 5.0);  // the referencing prim's, stronger
    EXPECT_EQ(flame.color, Rgb(1.0, 1.0, 1.0));  // the layer's
    EXPECT_DOUBLE_EQ(flame.transform[3][1], 84.0);

    try {
        (void)readScene(dir.write("bad.usda", "#usda 1.0\ndef OpalShadowFieldLight \"F\" (\n    references = "
                                              "@./scene.usda@\n)\n{\n}\n"),
                        assets);
        FAIL() << "a scene layer was read as a light layer";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("bad.usda:2:1: OpalShadowFieldLight </F>: references @./scene.usda@, "
                                             "which has no OpalShadowFieldLight prim"),
                  std::string::npos)
            << e.what();
    }
}

TEST(SceneSource, RenderSettingsTheDelegateRefusesNameTheAttribute) {
    class Refusing : public PullingDelegate {
        void setRenderSetting(const hd::Token& key, const hd::Value&) override {
            throw Error("unknown render setting '" + key + "'");
        }
    };
    const test::SceneDir dir;
    AssetCache assets;
    const std::filesystem::path file =
        dir.write("scene.usda", "#usda 1.0\ndef RenderSettings \"R\"\n{\n    bool opal:sparkles = 1\n}\n");
    const Scene scene = readScene(file, assets);
    Refusing delegate;
    try {
        applyRenderSettings(*scene.renderSettings, delegate);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), file.string() + ":4:5: RenderSettings </R>: attribute 'opal:sparkles': unknown "
                                                          "render setting 'opal:sparkles'");
    }
}

}  // namespace
}  // namespace opal::scene
