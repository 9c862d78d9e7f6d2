// Sync and commit: prims pull only when dirty, and commitResources redoes only what changed
// (renderStats() counts the work, the scene counts the pulls).
#include "delegate/render_delegate.h"

#include "tests/render/render_scene.h"

#include <gtest/gtest.h>

namespace opal {
namespace {

int stat(const hd::RenderDelegate& d, const std::string& name) {
    return std::get<int>(d.renderStats().at(name));
}

// Two spheres side by side, two lights, a material bound to the first sphere.
struct TwoSpheres {
    OpalRenderDelegate delegate;
    test::CountingScene scene;
    hd::RenderIndex index{delegate};

    TwoSpheres() {
        hd::MaterialDesc jade;
        jade.subsurface = test::sharedSphere()->defaultMaterial;
        scene.materials["/World/Looks/Jade"] = jade;
        index.insertSprim(hd::PrimType::Material, scene, "/World/Looks/Jade");
        test::addSphere(scene, index, "/World/A", test::translation(-6, 0, 0), "/World/Looks/Jade");
        test::addSphere(scene, index, "/World/B", test::translation(6, 0, 0));
        test::addCamera(scene, index);
        test::addLight(scene, index, "/World/Key", test::pointLight({0, 10, 15}, 400.0));
        test::addLight(scene, index, "/World/Rim", test::pointLight({0, -5, -20}, 200.0));
        index.sync();
        scene.pulls.clear();
    }
    test::Aovs render() { return test::renderAovs(delegate, index, test::CameraPath, 48, 32); }
};

TEST(Sync, FirstCommitEvaluatesEveryLightAtEveryMesh) {
    TwoSpheres s;
    EXPECT_EQ(stat(s.delegate, "commits"), 1);
    EXPECT_EQ(stat(s.delegate, "rayScenes"), 1);
    EXPECT_EQ(stat(s.delegate, "lightEvaluations"), 4);  // 2 lights x 2 meshes
    EXPECT_EQ(stat(s.delegate, "irradianceProducts"), 2);
    EXPECT_EQ(stat(s.delegate, "materialUpdates"), 2);
    EXPECT_EQ(s.delegate.meshPaths(), (std::vector<hd::SdfPath>{"/World/A", "/World/B"}));
    // primId is the mesh's place in path order.
    const test::Aovs a = s.render();
    EXPECT_EQ(a.at("primId", 12, 16)[0], 0.0f);  // A on the left
    EXPECT_EQ(a.at("primId", 36, 16)[0], 1.0f);
}

TEST(Sync, AMaterialEditRecomputesNeitherIrradianceNorProducts) {
    TwoSpheres s;
    const test::Aovs before = s.render();
    s.scene.materials["/World/Looks/Jade"].subsurface.sigmaA = {0.07, 0.12, 0.25};
    s.index.changeTracker().markDirty("/World/Looks/Jade", hd::Dirty::Material);
    s.index.sync();
    EXPECT_EQ(s.scene.totalPulls(), 1);  // the material only
    EXPECT_EQ(s.scene.pullCount("/World/Looks/Jade"), 1);
    EXPECT_EQ(stat(s.delegate, "lightEvaluations"), 4);    // unchanged
    EXPECT_EQ(stat(s.delegate, "irradianceProducts"), 2);  // unchanged
    EXPECT_EQ(stat(s.delegate, "materialUpdates"), 3);     // A only: B uses its asset's default
    EXPECT_EQ(stat(s.delegate, "rayScenes"), 1);
    EXPECT_EQ(std::get<double>(s.delegate.renderStats().at("irradianceMs")), 0.0);
    EXPECT_EQ(std::get<double>(s.delegate.renderStats().at("lightMomentsMs")), 0.0);
    EXPECT_EQ(std::get<double>(s.delegate.renderStats().at("productsMs")), 0.0);
    EXPECT_GT(std::get<double>(s.delegate.renderStats().at("materialMs")), 0.0);

    const test::Aovs after = s.render();
    // A (left) got less light back (more absorption); B (right) did not change.
    EXPECT_LT(test::sumRgb(after, "subsurface", 0, 24, 0, 32), 0.99 * test::sumRgb(before, "subsurface", 0, 24, 0, 32));
    EXPECT_EQ(test::sumRgb(after, "subsurface", 24, 48, 0, 32), test::sumRgb(before, "subsurface", 24, 48, 0, 32));

    // Rebinding B to the material is a material change of B alone.
    s.scene.meshes["/World/B"].material = "/World/Looks/Jade";
    s.index.changeTracker().markDirty("/World/B", hd::Dirty::Material);
    s.index.sync();
    EXPECT_EQ(stat(s.delegate, "materialUpdates"), 4);
    EXPECT_EQ(stat(s.delegate, "irradianceProducts"), 2);
}

TEST(Sync, AnEtaEditIsAMaterialEditToo) {
    TwoSpheres s;
    s.scene.materials["/World/Looks/Jade"].subsurface.eta = 1.45;
    s.index.changeTracker().markDirty("/World/Looks/Jade", hd::Dirty::Material);
    s.index.sync();
    EXPECT_EQ(stat(s.delegate, "lightEvaluations"), 4);
    EXPECT_EQ(stat(s.delegate, "irradianceProducts"), 2);
}

TEST(Sync, ALightEditPullsAndRecomputesThatLightOnly) {
    TwoSpheres s;
    s.scene.lights["/World/Key"].intensity = 800.0;
    s.index.changeTracker().markDirty("/World/Key", hd::Dirty::Params);
    s.index.sync();
    EXPECT_EQ(s.scene.totalPulls(), 1);
    EXPECT_EQ(s.scene.pullCount("/World/Key"), 1);
    EXPECT_EQ(stat(s.delegate, "lightEvaluations"), 4 + 2);  // the key light at both meshes
    EXPECT_EQ(stat(s.delegate, "irradianceProducts"), 2 + 2);
    EXPECT_EQ(stat(s.delegate, "materialUpdates"), 2);  // no material work
    EXPECT_EQ(stat(s.delegate, "rayScenes"), 1);
    const double moments = std::get<double>(s.delegate.renderStats().at("lightMomentsMs"));
    EXPECT_GT(moments, 0.0);  // the key light's moments, part of the irradiance time
    EXPECT_LE(moments, std::get<double>(s.delegate.renderStats().at("irradianceMs")));

    // Moving a light is the same.
    s.scene.lights["/World/Rim"].transform = test::translation(0, -8, -20);
    s.index.changeTracker().markDirty("/World/Rim", hd::Dirty::Transform);
    s.index.sync();
    EXPECT_EQ(s.scene.pullCount("/World/Rim"), 1);
    EXPECT_EQ(stat(s.delegate, "lightEvaluations"), 6 + 2);

    // Removing a light removes its contribution (no other light is recomputed).
    s.index.removePrim("/World/Rim");
    s.index.sync();
    EXPECT_EQ(stat(s.delegate, "lightEvaluations"), 8);
    EXPECT_EQ(stat(s.delegate, "irradianceProducts"), 4 + 2 + 2);
}

TEST(Sync, ARemovedLightLeavesTheImageOfTheOthers) {
    TwoSpheres s;
    s.index.removePrim("/World/Rim");
    s.index.sync();
    const test::Aovs removed = s.render();

    TwoSpheres fresh;
    fresh.index.removePrim("/World/Rim");
    fresh.index.removePrim("/World/Key");
    fresh.index.sync();
    test::addLight(fresh.scene, fresh.index, "/World/Key", fresh.scene.lights["/World/Key"]);
    fresh.index.sync();
    const test::Aovs keyOnly = fresh.render();
    EXPECT_LT(test::maxRelativeDifference(removed.data.at("color"), keyOnly.data.at("color")), 1e-5);
}

TEST(Sync, MovingAMeshRelightsItAndReshadowsTheOthers) {
    TwoSpheres s;
    s.scene.meshes["/World/B"].transform = test::translation(7, 1, 0);
    s.index.changeTracker().markDirty("/World/B", hd::Dirty::Transform);
    s.index.sync();
    EXPECT_EQ(s.scene.totalPulls(), 1);
    EXPECT_EQ(stat(s.delegate, "rayScenes"), 2);
    // B: both lights (its samples moved); A: both analytic lights' shadows (an occluder moved).
    EXPECT_EQ(stat(s.delegate, "lightEvaluations"), 4 + 4);
    EXPECT_EQ(stat(s.delegate, "irradianceProducts"), 2 + 2);
    EXPECT_EQ(stat(s.delegate, "materialUpdates"), 2);

    // A transform dirty bit with the same matrix does nothing.
    s.index.changeTracker().markDirty("/World/B", hd::Dirty::Transform);
    s.index.sync();
    EXPECT_EQ(stat(s.delegate, "rayScenes"), 2);
    EXPECT_EQ(stat(s.delegate, "lightEvaluations"), 8);
}

TEST(Sync, AnOccluderCastsShadowsOnTheOtherMesh) {
    // The key light straight above A; B moved between them darkens A's top.
    TwoSpheres s;
    s.scene.lights["/World/Key"] = test::pointLight({-6, 30, 0}, 2000.0);
    s.index.changeTracker().markDirty("/World/Key", hd::Dirty::Params);
    s.index.removePrim("/World/Rim");
    s.index.sync();
    const test::Aovs lit = s.render();
    s.scene.meshes["/World/B"].transform = test::translation(-6, 15, 0);
    s.index.changeTracker().markDirty("/World/B", hd::Dirty::Transform);
    s.index.sync();
    const test::Aovs shadowed = s.render();
    const double before = test::sumRgb(lit, "irradiance", 0, 24, 0, 32);
    const double after = test::sumRgb(shadowed, "irradiance", 0, 24, 0, 32);
    EXPECT_LT(after, 0.5 * before);
}

TEST(Sync, HiddenMeshesAreNeitherRenderedNorRelit) {
    TwoSpheres s;
    s.scene.meshes["/World/B"].visible = false;
    s.index.changeTracker().markDirty("/World/B", hd::Dirty::Visibility);
    s.index.sync();
    EXPECT_EQ(stat(s.delegate, "rayScenes"), 2);
    const int evaluations = stat(s.delegate, "lightEvaluations");
    EXPECT_EQ(evaluations, 4 + 2);  // A re-shadowed (B no longer occludes); B skipped
    const test::Aovs hidden = s.render();
    for (float id : hidden.data.at("primId")) EXPECT_NE(id, 1.0f);

    // A light edit while B is hidden touches A only; showing B relights it in full.
    s.scene.lights["/World/Key"].intensity = 500.0;
    s.index.changeTracker().markDirty("/World/Key", hd::Dirty::Params);
    s.index.sync();
    EXPECT_EQ(stat(s.delegate, "lightEvaluations"), evaluations + 1);
    s.scene.meshes["/World/B"].visible = true;
    s.index.changeTracker().markDirty("/World/B", hd::Dirty::Visibility);
    s.index.sync();
    EXPECT_EQ(stat(s.delegate, "lightEvaluations"), evaluations + 1 + 2 + 2);  // B in full, A re-shadowed
    const test::Aovs shown = s.render();
    EXPECT_EQ(shown.at("primId", 36, 16)[0], 1.0f);
}

TEST(Sync, ANewAssetRebuildsTheMesh) {
    TwoSpheres s;
    s.scene.meshes["/World/B"].asset = test::sphereAsset(2, 4.0f, 4);
    s.index.changeTracker().markDirty("/World/B", hd::Dirty::Topology);
    s.index.sync();
    EXPECT_EQ(stat(s.delegate, "rayScenes"), 2);
    EXPECT_EQ(stat(s.delegate, "lightEvaluations"), 4 + 2 + 2);  // B in full, A re-shadowed
    EXPECT_EQ(stat(s.delegate, "irradianceProducts"), 2 + 2);
    EXPECT_EQ(stat(s.delegate, "materialUpdates"), 2 + 1);  // the new engine takes B's material
}

TEST(Sync, RemovingAMaterialItsMeshStillUsesIsAnError) {
    TwoSpheres s;
    s.index.removePrim("/World/Looks/Jade");
    try {
        s.index.sync();
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("/World/A"), std::string::npos) << m;
        EXPECT_NE(m.find("/World/Looks/Jade"), std::string::npos) << m;
    }
    // Rebinding A to its default material recovers.
    s.scene.meshes["/World/A"].material.clear();
    s.index.changeTracker().markDirty("/World/A", hd::Dirty::Material);
    EXPECT_NO_THROW(s.index.sync());
}

TEST(Sync, MaterialsOutsideTheEditableRangeAreClampedWithAWarning) {
    TwoSpheres s;
    s.scene.materials["/World/Looks/Jade"].subsurface.sigmaA = {100.0, 0.1, 0.2};
    s.index.changeTracker().markDirty("/World/Looks/Jade", hd::Dirty::Material);
    s.index.sync();
    const std::vector<std::string> warnings = s.delegate.takeWarnings();
    ASSERT_FALSE(warnings.empty());
    EXPECT_NE(warnings[0].find("/World/A"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("/World/Looks/Jade"), std::string::npos) << warnings[0];
    EXPECT_TRUE(s.delegate.takeWarnings().empty());
}

TEST(Sync, SwitchingToReferenceAndBackReusesTheEngine) {
    TwoSpheres s;
    s.delegate.setRenderSetting("opal:reference", true);
    s.index.sync();  // nothing dirty: the delegate still commits the setting
    EXPECT_EQ(stat(s.delegate, "referenceGathers"), 2);
    EXPECT_EQ(stat(s.delegate, "lightEvaluations"), 4);
    // A material edit in reference mode gathers again (the exact gather has no cache).
    s.scene.materials["/World/Looks/Jade"].subsurface.eta = 1.35;
    s.index.changeTracker().markDirty("/World/Looks/Jade", hd::Dirty::Material);
    s.index.sync();
    EXPECT_EQ(stat(s.delegate, "referenceGathers"), 3);
    s.delegate.setRenderSetting("opal:reference", false);
    s.index.sync();
    EXPECT_EQ(stat(s.delegate, "irradianceProducts"), 2);  // the engine's products were still current
    EXPECT_EQ(stat(s.delegate, "lightEvaluations"), 4);
}

}  // namespace
}  // namespace opal
