// The layer the viewer saves, read back by the scene reader opal-render uses (the independent
// truth): every mesh, material, light and camera comes back at its path with the same
// description, bit for bit; a disabled light is left out; the viewer's own prims move to a
// root the scene does not use; asset paths are re-anchored at the new layer.
#include "examples/opal-view/core/edited_scene.h"
#include "examples/opal-view/core/pixel_probe.h"
#include "examples/opal-view/core/usda_export.h"
#include "examples/scene/scene_reader.h"
#include "tests/view/view_process.h"

#include <gtest/gtest.h>

namespace opal::view {
namespace {

Imath::M44d placed(double degrees, const Imath::V3d& at) {
    Imath::M44d m;
    m.setEulerAngles(Imath::V3d(0.3, degrees * M_PI / 180.0, -0.1));
    m[3][0] = at.x, m[3][1] = at.y, m[3][2] = at.z;
    return m;
}

scene::SceneLight light(hd::Token type, hd::LightKind kind, const Imath::M44d& at) {
    hd::LightDesc desc;
    desc.kind = kind;
    desc.transform = at;
    desc.color = Rgb{1.0, 0.75, 0.5};
    desc.intensity = 300.0;
    desc.exposure = -0.5;
    return {std::move(type), desc, {}};
}

// A scene as the viewer holds it: a mesh at </OpalView/Statue> (so the viewer's prims must
// go elsewhere), its material and the camera under </_OpalView>, a spot light, a disabled
// sun and a textured dome.
SceneExport editedScene(const test::SceneDir& dir, scene::AssetCache& assets) {
    SceneExport out;
    scene::Scene& scene = out.scene;
    scene.file = dir / "scene.usda";
    scene.metersPerUnit = 0.001;
    const std::filesystem::path asset = dir.writeSphereAsset("sphere");
    hd::MeshDesc mesh{assets.load(asset), placed(20.0, {1.0, 2.0, 3.0}), "/_OpalView/Materials/Statue", true};
    scene.meshes["/OpalView/Statue"] = {mesh, asset, {}};
    hd::MaterialDesc material;
    material.subsurface = Material{{1.5, 1.25, 1.0}, {0.0625, 0.125, 0.25}, 1.375};
    material.specularRoughness = 0.5;
    scene.materials["/_OpalView/Materials/Statue"] = {material, {}};
    scene::SceneLight spot = light(hd::PrimType::SphereLight, hd::LightKind::Sphere, placed(-30.0, {-8.0, 6.0, 20.0}));
    spot.desc.radius = 0.75;
    spot.desc.shapingConeAngle = 40.0;
    spot.desc.shapingConeSoftness = 0.25;
    scene.lights["/_OpalView/Lights/Spot"] = spot;
    scene.lights["/Sun"] = light(hd::PrimType::DistantLight, hd::LightKind::Distant, placed(45.0, {0.0, 0.0, 0.0}));
    scene::SceneLight dome = light(hd::PrimType::DomeLight, hd::LightKind::Dome, placed(90.0, {0.0, 0.0, 0.0}));
    dome.desc.textureFile = dir.write("maps/room.exr", "a file that exists").string();
    dome.desc.textureColorSpace = "ACEScg";
    scene.lights["/Sky"] = dome;
    hd::CameraDesc camera;
    camera.transform = placed(10.0, {0.0, 1.0, 40.0});
    camera.nearClip = 0.5;
    camera.farClip = 512.0;
    scene.cameras["/_OpalView/Camera"] = {camera, {}};
    out.disabledLights = {"/Sun"};
    out.camera = "/_OpalView/Camera";
    out.width = 64;
    out.height = 48;
    out.settings = {{"opal:samplesPerPixel", 4}};
    return out;
}

TEST(UsdaExport, TheSceneReaderReadsBackEveryPrimAsTheViewerHeldIt) {
    const test::SceneDir dir;
    scene::AssetCache assets;
    const SceneExport out = editedScene(dir, assets);
    const std::filesystem::path saved = dir / "out/saved.usda";
    std::filesystem::create_directories(saved.parent_path());
    saveSceneLayer(out, saved);
    const scene::Scene back = scene::readScene(saved, assets);

    ASSERT_EQ(back.meshes.count("/OpalView/Statue"), 1u);
    const hd::MeshDesc& mesh = back.meshes.at("/OpalView/Statue").desc;
    EXPECT_EQ(mesh.transform, out.scene.meshes.at("/OpalView/Statue").desc.transform);
    EXPECT_EQ(mesh.material, "/OpalView2/Materials/Statue");
    EXPECT_TRUE(sameMaterial(back.materials.at("/OpalView2/Materials/Statue").desc,
                             out.scene.materials.at("/_OpalView/Materials/Statue").desc));
    EXPECT_TRUE(sameLight(back.lights.at("/OpalView2/Lights/Spot").desc, out.scene.lights.at("/_OpalView/Lights/Spot").desc));
    EXPECT_TRUE(sameLight(back.lights.at("/Sky").desc, out.scene.lights.at("/Sky").desc));
    EXPECT_EQ(back.lights.count("/Sun"), 0u) << "a disabled light is written invisible";
    EXPECT_EQ(back.lights.size(), 2u);
    const hd::CameraDesc& camera = back.cameras.at("/OpalView2/Camera").desc;
    const hd::CameraDesc& held = out.scene.cameras.at("/_OpalView/Camera").desc;
    EXPECT_EQ(camera.transform, held.transform);
    EXPECT_EQ(camera.nearClip, held.nearClip);
    EXPECT_EQ(camera.farClip, held.farClip);
    EXPECT_EQ(camera.focalLength, held.focalLength);
    ASSERT_TRUE(back.renderSettings);
    EXPECT_EQ(back.renderSettings->camera, "/OpalView2/Camera");
    EXPECT_EQ(back.renderSettings->resolution, (scene::Resolution{64, 48}));
    ASSERT_EQ(back.renderSettings->delegateSettings.size(), 1u);
    EXPECT_EQ(back.renderSettings->delegateSettings[0].name, "opal:samplesPerPixel");
    EXPECT_EQ(back.renderSettings->delegateSettings[0].value, hd::Value(4));

    const std::string layer = test::slurpFile(saved);
    EXPECT_NE(layer.find("@../sphere.usda@"), std::string::npos) << layer;
    EXPECT_NE(layer.find("@../maps/room.exr@"), std::string::npos) << layer;
}

TEST(PixelProbe, APrimIdNamesTheMeshesByPathThenTheRenderedShadowFieldLights) {
    scene::Scene scene;
    for (const char* path : {"/B", "/A"}) scene.meshes[path] = {};
    scene::SceneLight field;
    field.desc.kind = hd::LightKind::ShadowField;
    for (const char* path : {"/Flame1", "/Flame2", "/Flame3"}) scene.lights[path] = field;
    scene.lights["/Key"] = {};
    EXPECT_EQ(primOfId(scene, {}, 0.0f), "/A");
    EXPECT_EQ(primOfId(scene, {}, 1.0f), "/B");
    EXPECT_EQ(primOfId(scene, {}, 3.0f), "/Flame2");
    EXPECT_EQ(primOfId(scene, {"/Flame1"}, 3.0f), "/Flame3");
    EXPECT_EQ(primOfId(scene, {}, -1.0f), std::nullopt);
    EXPECT_EQ(primOfId(scene, {}, 5.0f), std::nullopt);
    EXPECT_EQ(primOfId(scene, {}, 0.5f), std::nullopt);
}

}  // namespace
}  // namespace opal::view
