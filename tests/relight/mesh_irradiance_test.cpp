#include "delegate/relight/mesh_irradiance.h"

#include "raytrace/ray_scene.h"
#include "delegate/relight/relight_engine.h"
#include "schema/error.h"
#include "synthetic_asset.h"
#include "tests/relight/translation.h"

#include <gtest/gtest.h>

#include <numbers>

namespace opal {
namespace {


using test::translation;

hd::LightDesc pointLight(const Imath::V3d& at, double intensity) {
    hd::LightDesc d;
    d.kind = hd::LightKind::Sphere;
    d.treatAsPoint = true;
    d.intensity = intensity;
    d.transform = translation(at.x, at.y, at.z);
    return d;
}

hd::LightDesc distantLight(const Imath::M44d& transform) {
    hd::LightDesc d;
    d.kind = hd::LightKind::Distant;
    d.normalize = true;
    d.color = {0.2, 0.6, 1.0};
    d.transform = transform;
    return d;
}

// A sphere of radius 5 mm with a basis and the lossless transfer, and a ray scene holding it.
struct SphereScene {
    std::shared_ptr<TranslucentAsset> asset = std::make_shared<TranslucentAsset>();
    RayScene rays;

    explicit SphereScene(const Imath::M44d& transform = Imath::M44d()) {
        test::makeCubeSphere(*asset, 3, 5.0f);
        asset->defaultMaterial = Material{{1.2, 0.9, 0.7}, {0.05, 0.1, 0.2}, 1.4};
        asset->range = test::rangeAround(asset->defaultMaterial, 2.0, 1.2, 1.6);
        asset->basis = test::fitBasis(asset->range, 8, 12.0);
        test::buildTransfer(*asset, 1.0, 1.0);
        rays.addMesh(asset->mesh, transform);
        rays.commit();
    }
};

TEST(MeshIrradiance, TwoLightsGiveTheSumOfEachAlone) {
    SphereScene scene;
    const AnalyticLight a = AnalyticLight::fromDesc(pointLight({9, 6, 3}, 40.0));
    Imath::M44d tilt;
    tilt.setAxisAngle(Imath::V3d(1, 0, 0), 0.7);
    const AnalyticLight b = AnalyticLight::fromDesc(distantLight(tilt));

    MeshIrradiance both(scene.asset, Imath::M44d()), onlyA(scene.asset, Imath::M44d()), onlyB(scene.asset, Imath::M44d());
    both.setLight("/a", a, scene.rays);
    both.setLight("/b", b, scene.rays);
    onlyA.setLight("/a", a, scene.rays);
    onlyB.setLight("/b", b, scene.rays);
    IrradianceMoments sum = onlyA.moments();
    sum += onlyB.moments();
    EXPECT_LT(test::maxRelative(both.moments().values, sum.values), 1e-6);

    // The relit radiance is linear in the lights too.
    RelightEngine engine(scene.asset), engineA(scene.asset), engineB(scene.asset);
    engine.setIrradiance(both.moments());
    engineA.setIrradiance(onlyA.moments());
    engineB.setIrradiance(onlyB.moments());
    std::vector<float> summed(engineA.sampleRadiance().begin(), engineA.sampleRadiance().end());
    for (std::size_t j = 0; j < summed.size(); ++j) summed[j] += engineB.sampleRadiance()[j];
    EXPECT_LT(test::maxRelative(engine.sampleRadiance(), summed), 1e-5);

    // Half the sphere faces away from each light: shadowed samples get nothing.
    std::size_t dark = 0;
    for (std::uint32_t i = 0; i < onlyA.moments().samples; ++i) dark += onlyA.moments().sample(i)[0] == 0.0f;
    EXPECT_GT(dark, onlyA.moments().samples / 3);
}

TEST(MeshIrradiance, EditingOneLightKeepsTheOthers) {
    SphereScene scene;
    MeshIrradiance irradiance(scene.asset, Imath::M44d());
    irradiance.setLight("/a", AnalyticLight::fromDesc(pointLight({9, 6, 3}, 40.0)), scene.rays);
    irradiance.setLight("/b", AnalyticLight::fromDesc(pointLight({-8, 1, -4}, 25.0)), scene.rays);
    const std::vector<float> original = irradiance.moments().values;
    irradiance.setLight("/a", AnalyticLight::fromDesc(pointLight({0, 10, 0}, 40.0)), scene.rays);
    EXPECT_GT(test::maxRelative(irradiance.moments().values, original), 0.1);
    irradiance.setLight("/a", AnalyticLight::fromDesc(pointLight({9, 6, 3}, 40.0)), scene.rays);
    EXPECT_LT(test::maxRelative(irradiance.moments().values, original), 1e-6);

    MeshIrradiance onlyB(scene.asset, Imath::M44d());
    onlyB.setLight("/b", AnalyticLight::fromDesc(pointLight({-8, 1, -4}, 25.0)), scene.rays);
    irradiance.removeLight("/a");
    EXPECT_LT(test::maxRelative(irradiance.moments().values, onlyB.moments().values), 1e-6);
}

TEST(MeshIrradiance, MovingMeshAndLightsTogetherChangesNothing) {
    Imath::M44d move;
    move.setAxisAngle(Imath::V3d(0.3, 1, 0.2).normalized(), 1.1);
    move = move * translation(4, -2, 7);
    SphereScene still, moved(move);
    const auto moveLight = [&](hd::LightDesc d) {
        d.transform = d.transform * move;
        return AnalyticLight::fromDesc(d);
    };
    MeshIrradiance a(still.asset, Imath::M44d()), b(moved.asset, move);
    a.setLight("/p", AnalyticLight::fromDesc(pointLight({9, 6, 3}, 40.0)), still.rays);
    a.setLight("/d", AnalyticLight::fromDesc(distantLight(Imath::M44d())), still.rays);
    b.setLight("/p", moveLight(pointLight({9, 6, 3}, 40.0)), moved.rays);
    b.setLight("/d", moveLight(distantLight(Imath::M44d())), moved.rays);
    EXPECT_LT(test::maxRelative(b.moments().values, a.moments().values), 1e-4);

    // setTransform re-places the samples: back at the origin, the same as `a`.
    RayScene origin;
    origin.addMesh(still.asset->mesh, Imath::M44d());
    origin.commit();
    b.setTransform(Imath::M44d(), origin);
    EXPECT_GT(test::maxRelative(b.moments().values, a.moments().values), 1e-2);  // lights stayed moved
    b.setLight("/p", AnalyticLight::fromDesc(pointLight({9, 6, 3}, 40.0)), origin);
    b.setLight("/d", AnalyticLight::fromDesc(distantLight(Imath::M44d())), origin);
    EXPECT_LT(test::maxRelative(b.moments().values, a.moments().values), 1e-6);
}

TEST(MeshIrradiance, OccluderUpdateReshadowsAnalyticLights) {
    SphereScene scene;
    MeshIrradiance irradiance(scene.asset, Imath::M44d());
    irradiance.setLight("/p", AnalyticLight::fromDesc(pointLight({0, 20, 0}, 400.0)), scene.rays);
    const std::vector<float> open = irradiance.moments().values;

    RayScene blocked;  // the sphere and a large plate between it and the light
    blocked.addMesh(scene.asset->mesh, Imath::M44d());
    RenderMesh plate;
    plate.points = {{-20, 10, -20}, {20, 10, -20}, {20, 10, 20}, {-20, 10, 20}};
    plate.faceVertexCounts = {4};
    plate.faceVertexIndices = {0, 1, 2, 3};
    blocked.addMesh(plate, Imath::M44d());
    blocked.commit();
    irradiance.updateShadows(blocked);
    for (float e : irradiance.moments().values) EXPECT_EQ(e, 0.0f);
    irradiance.updateShadows(scene.rays);
    EXPECT_LT(test::maxRelative(irradiance.moments().values, open), 1e-6);
}

TEST(MeshIrradiance, ExactIrradianceUsesTheExactFresnelFactor) {
    SphereScene scene;
    MeshIrradiance irradiance(scene.asset, Imath::M44d());
    irradiance.setLight("/p", AnalyticLight::fromDesc(pointLight({0, 20, 0}, 400.0)), scene.rays);
    for (double eta : {1.2, 1.45, 1.6}) {
        const std::vector<float> exact = irradiance.exactIrradiance(eta);
        const std::vector<float> moments = irradiance.moments().combine(fresnelMoments(eta, 2));
        EXPECT_LT(test::relativeRmse(moments, exact), 2e-3) << eta;
        // The top sample faces the light: E = I F_t(eta, 1) / d^2, d = 20 - 5.
        std::size_t top = 0;
        for (std::size_t i = 0; i < scene.asset->samples.size(); ++i)
            if (scene.asset->samples[i].position.y > scene.asset->samples[top].position.y) top = i;
        const double d = 20.0 - scene.asset->samples[top].position.y;
        const double mu = scene.asset->samples[top].normal.dot(
            (Imath::V3f(0, 20, 0) - scene.asset->samples[top].position).normalized());
        EXPECT_NEAR(exact[3 * top], std::numbers::pi * 400.0 * mu * fresnelTransmittance(eta, mu) /
                                        (Imath::V3f(0, 20, 0) - scene.asset->samples[top].position).length2(),
                    1e-4 * exact[3 * top])
            << d;
    }
}

TEST(MeshIrradiance, RejectsNonUniformScale) {
    SphereScene scene;
    Imath::M44d squash;
    squash.setScale(Imath::V3d(1, 2, 1));
    EXPECT_THROW(MeshIrradiance(scene.asset, squash), Error);
    Imath::M44d uniform;
    uniform.setScale(2.0);
    EXPECT_NO_THROW(MeshIrradiance(scene.asset, uniform));
}

}  // namespace
}  // namespace opal
