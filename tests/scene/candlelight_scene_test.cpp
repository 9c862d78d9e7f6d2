// The shipped candlelight scene read by the scene reader on its real (small) assets: the
// candle and the wick share one frame, their materials lie inside their assets' baked
// ranges (nothing is clamped), and the flame light stands just above the wick's tip, as
// read from the baked wick's mesh and the scene's light transform.
#include "examples/scene/scene_reader.h"
#include "schema/asset/asset_layer.h"
#include "tests/scene/candle_scene_assets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace opal::scene {
namespace {

const SceneMesh& meshAt(const Scene& scene, const std::string& path) {
    const auto it = scene.meshes.find(hd::SdfPath(path));
    if (it == scene.meshes.end()) throw Error("the scene has no mesh " + path);
    return it->second;
}

TEST(CandlelightScene, ReadsWithTheCandleWickFlameAndRoom) {
    const test::SceneDir dir;
    const std::filesystem::path file = test::writeCandleScene(dir);
    AssetCache assets;
    const Scene scene = readScene(file, assets);
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
    ASSERT_EQ(scene.meshes.size(), 2u);
    ASSERT_EQ(scene.lights.size(), 2u);
    const SceneLight& flame = scene.lights.at(hd::SdfPath("/World/Lights/Flame"));
    EXPECT_EQ(flame.desc.kind, hd::LightKind::ShadowField);
    // The light references the light layer; its opal:field is the sidecar beside it.
    const std::filesystem::path field(flame.desc.shadowField);
    EXPECT_EQ(field.parent_path(), dir.path()) << field;
    EXPECT_TRUE(field.filename().string().starts_with("flame.") && field.extension() == ".opal") << field;
    EXPECT_EQ(scene.lights.at(hd::SdfPath("/World/Lights/Room")).desc.kind, hd::LightKind::Dome);

    // Each translucent mesh's bound material lies inside its asset's editable range.
    for (const auto& [mesh, material] : {std::pair{"/World/Candle", "/World/Looks/Wax"},
                                         std::pair{"/World/Wick", "/World/Looks/Char"}}) {
        const SceneMesh& m = meshAt(scene, mesh);
        EXPECT_EQ(m.desc.material, hd::SdfPath(material)) << mesh;
        const Material& bound = scene.materials.at(hd::SdfPath(material)).desc.subsurface;
        EXPECT_TRUE(readAsset(m.assetFile).range.contains(bound)) << material << " would be clamped";
        EXPECT_EQ(m.desc.transform, Imath::M44d()) << mesh << ": the candle and the wick share the asset frame";
    }
    // opal-bake names a built-in mesh's asset after it.
    EXPECT_EQ(readAsset(meshAt(scene, "/World/Wick").assetFile).name, "wick");
}

// The flame's base (the light's origin, flame_emitter.h) sits on the wick's tip: above
// it by at most a millimetre, and over it (within a millimetre sideways).
TEST(CandlelightScene, TheFlameStandsJustAboveTheWicksTip) {
    const test::SceneDir dir;
    const std::filesystem::path file = test::writeCandleScene(dir);
    AssetCache assets;
    const Scene scene = readScene(file, assets);
    const TranslucentAsset wick = readAsset(meshAt(scene, "/World/Wick").assetFile);
    const Imath::V3f tip = *std::max_element(wick.mesh.points.begin(), wick.mesh.points.end(),
                                             [](const Imath::V3f& a, const Imath::V3f& b) { return a.y < b.y; });
    const Imath::M44d& light = scene.lights.at(hd::SdfPath("/World/Lights/Flame")).desc.transform;
    const Imath::V3d base = Imath::V3d(0.0) * light;
    EXPECT_GT(base.y, tip.y);
    EXPECT_LT(base.y, tip.y + 1.0);
    EXPECT_LT(std::hypot(base.x - tip.x, base.z - tip.z), 1.0);
    // The candle's top is below the flame: the flame does not start inside the wax.
    const TranslucentAsset candle = readAsset(meshAt(scene, "/World/Candle").assetFile);
    for (const Imath::V3f& p : candle.mesh.points) {
        if (std::hypot(p.x - base.x, p.z - base.z) < 4.0) {
            EXPECT_LT(p.y, base.y - 5.0);
        }
    }
}

}  // namespace
}  // namespace opal::scene
