// The lights the viewer adds and their type-specific parameters, without a window. Truths:
// the renderer's own light model (delegate/relight/analytic_light.h) gives the irradiance
// new_light.h promises (pi at the object's centre, E = pi I / d^2 for a point, pi L r^2 / d^2
// for a sphere); a new spot's cone holds the whole object and nothing far off its axis;
// each parameter has the scene reader's range and belongs to its light types only.
#include "delegate/relight/analytic_light.h"
#include "examples/opal-view/core/light_shape.h"
#include "examples/opal-view/core/new_light.h"
#include "schema/error.h"

#include <gtest/gtest.h>

#include <numbers>

namespace opal::view {
namespace {

const BoundingSphere ObjectBounds{{4.0, -2.0, 7.0}, 5.0};

double irradianceAt(const hd::LightDesc& desc, const Imath::V3d& point) {
    const std::optional<Incidence> in = AnalyticLight::fromDesc(desc).incidence(point);
    return in ? in->normalIrradiance[1] : 0.0;
}

std::string refusal(hd::LightDesc light, const char* parameter, double value) {
    const hd::LightDesc before = light;
    try {
        setShapeParameter(light, parameter, value);
    } catch (const Error& e) {
        EXPECT_EQ(light.radius, before.radius);
        EXPECT_EQ(light.shapingConeAngle, before.shapingConeAngle);
        EXPECT_EQ(light.angle, before.angle);
        return e.what();
    }
    return "";
}

TEST(NewLight, EveryKindIsNamedAndAddable) {
    ASSERT_EQ(newLightKinds().size(), 5u);
    for (const NewLightKind kind : newLightKinds()) EXPECT_EQ(newLightKind(newLightKindName(kind)), kind);
    EXPECT_EQ(newLightKind("spot"), NewLightKind::Spot);
    EXPECT_EQ(newLightKind("sphere"), NewLightKind::Sphere);
    EXPECT_FALSE(newLightKind("area"));
}

TEST(NewLight, PointSphereAndSpotLightTheCentreWithIrradiancePi) {
    for (const NewLightKind kind : {NewLightKind::Point, NewLightKind::Sphere, NewLightKind::Spot}) {
        const scene::SceneLight light = newLight(kind, ObjectBounds);
        EXPECT_EQ(light.primType, hd::PrimType::SphereLight);
        EXPECT_NEAR(irradianceAt(light.desc, ObjectBounds.center), std::numbers::pi, 1e-5) << newLightKindName(kind);
    }
    const hd::LightDesc sphere = newLight(NewLightKind::Sphere, ObjectBounds).desc;
    EXPECT_FALSE(sphere.treatAsPoint);
    EXPECT_EQ(sphere.radius, 0.25 * ObjectBounds.radius);
    EXPECT_FALSE(sphere.shapingConeAngle);
}

TEST(NewLight, ANewSpotAimsAtTheObjectAndItsConeHoldsAllOfIt) {
    const hd::LightDesc spot = newLight(NewLightKind::Spot, ObjectBounds).desc;
    ASSERT_TRUE(spot.shapingConeAngle);
    const Imath::V3d at(spot.transform[3][0], spot.transform[3][1], spot.transform[3][2]);
    const Imath::V3d toCentre = (ObjectBounds.center - at).normalized();
    // Points on the object's bounding sphere across the light's view: lit, at most 19.5
    // degrees off the axis; a point 60 degrees off it is not.
    const Imath::V3d across = toCentre.cross(Imath::V3d(0.0, 1.0, 0.0)).normalized();
    for (const Imath::V3d& side : {across, -across, toCentre.cross(across)})
        EXPECT_GT(irradianceAt(spot, ObjectBounds.center + side * ObjectBounds.radius), 0.0);
    Imath::V3d off = toCentre * std::cos(std::numbers::pi / 3.0) + across * std::sin(std::numbers::pi / 3.0);
    EXPECT_EQ(irradianceAt(spot, at + off * 15.0), 0.0);
}

TEST(LightShape, EachParameterSetsItsFieldWithinTheReadersRange) {
    hd::LightDesc spot = newLight(NewLightKind::Spot, ObjectBounds).desc;
    setShapeParameter(spot, "radius", 0.5);
    setShapeParameter(spot, "cone", 12.5);
    setShapeParameter(spot, "softness", 0.75);
    EXPECT_EQ(spot.radius, 0.5);
    EXPECT_EQ(spot.shapingConeAngle, 12.5);
    EXPECT_EQ(spot.shapingConeSoftness, 0.75);
    hd::LightDesc sphere = newLight(NewLightKind::Sphere, ObjectBounds).desc;
    setShapeParameter(sphere, "cone", 40.0);
    EXPECT_EQ(sphere.shapingConeAngle, 40.0) << "a cone makes a sphere light a spot";
    hd::LightDesc sun = newLight(NewLightKind::Distant, ObjectBounds).desc;
    setShapeParameter(sun, "angle", 5.0);
    EXPECT_EQ(sun.angle, 5.0);

    EXPECT_EQ(refusal(spot, "cone", 181.0), "cone 181 is outside 0 to 180 degrees");
    EXPECT_EQ(refusal(spot, "softness", -0.5), "softness -0.5 is outside 0 to 1");
    EXPECT_EQ(refusal(spot, "radius", -1.0), "radius -1 is negative");
    EXPECT_EQ(refusal(sun, "angle", 200.0), "angle 200 is outside 0 to 180 degrees");
}

TEST(LightShape, AParameterOfAnotherLightTypeIsRefusedNamingWhichHaveIt) {
    const hd::LightDesc point = newLight(NewLightKind::Point, ObjectBounds).desc;
    const hd::LightDesc sphere = newLight(NewLightKind::Sphere, ObjectBounds).desc;
    const hd::LightDesc sun = newLight(NewLightKind::Distant, ObjectBounds).desc;
    const hd::LightDesc dome = newLight(NewLightKind::Dome, ObjectBounds).desc;
    EXPECT_EQ(refusal(point, "radius", 1.0), "only sphere and spot lights have a radius (not a point light: treatAsPoint)");
    EXPECT_EQ(refusal(sphere, "softness", 0.5), "only spot lights have a softness (set a cone first)");
    EXPECT_EQ(refusal(sun, "cone", 10.0), "only sphere, point and spot lights have a cone");
    EXPECT_EQ(refusal(dome, "angle", 1.0), "only distant lights have an angle");
    EXPECT_EQ(refusal(sphere, "width", 1.0), "unknown light parameter 'width' (radius, cone, softness, angle)");
    EXPECT_TRUE(hasShapeParameter(point, "cone"));
    EXPECT_FALSE(hasShapeParameter(dome, "radius"));
}

}  // namespace
}  // namespace opal::view
