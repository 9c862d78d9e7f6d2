#include "delegate/relight/analytic_light.h"

#include "delegate/relight/fresnel_response.h"
#include "raytrace/ray_scene.h"
#include "schema/error.h"
#include "schema/scatter/acescg_from_xyz.h"
#include "schema/scatter/blackbody.h"
#include "schema/scatter/dipole.h"
#include "schema/scatter/fresnel_moments.h"
#include "tests/relight/translation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace opal {
namespace {


PlacedSamples oneSample(const Imath::V3f& position, const Imath::V3f& normal) {
    PlacedSamples s;
    s.positions.push_back(position);
    s.normals.push_back(normal);
    return s;
}

using test::translation;

// E at one sample, exact F_t and through the moments (2 terms, response over [1.2, 1.6]).
struct Irradiance {
    Imath::V3f exact, moments;
};

Irradiance irradianceAt(const AnalyticLight& light, const PlacedSamples& sample, double eta,
                        const RayScene* scene = nullptr) {
    const std::vector<LightArrival> arrivals = lightArrivals(light, sample, scene, 1e-4f);
    std::vector<float> exact(3, 0.0f);
    addExactIrradiance(arrivals, eta, exact);
    IrradianceMoments moments(1, 2);
    addMoments(arrivals, FresnelResponse(1.2, 1.6, 2), moments);
    const std::vector<float> combined = moments.combine(fresnelMoments(eta, 2));
    return {{exact[0], exact[1], exact[2]}, {combined[0], combined[1], combined[2]}};
}

void expectRgbNear(const Imath::V3f& a, const Rgb& b, double relative) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], relative * std::abs(b[c]) + 1e-12) << "channel " << c;
}

TEST(AnalyticLight, PointLightFollowsInverseSquareAndCosineLaws) {
    hd::LightDesc desc;
    desc.kind = hd::LightKind::Sphere;
    desc.treatAsPoint = true;
    desc.color = {1.0, 0.5, 0.25};
    desc.intensity = 3.0;
    desc.exposure = 1.0;
    desc.transform = translation(1.0, 2.0, 0.5);
    const AnalyticLight light = AnalyticLight::fromDesc(desc);
    const PlacedSamples sample = oneSample({0, 0, 0}, {0, 1, 0});
    const double d2 = 1.0 + 4.0 + 0.25, mu = 2.0 / std::sqrt(d2);
    const Rgb intensity = desc.color * (std::numbers::pi * 3.0 * 2.0);  // I = pi color intensity 2^exposure
    for (double eta : {1.2, 1.4, 1.6}) {
        const Irradiance e = irradianceAt(light, sample, eta);
        const Rgb expected = intensity * (mu * fresnelTransmittance(eta, mu) / d2);  // I cos F_t / d^2
        expectRgbNear(e.exact, expected, 1e-6);
        expectRgbNear(e.moments, expected, 2e-3);
    }
    // With normalize, a point light's intensity is L_e / 4.
    desc.normalize = true;
    const Irradiance normalized = irradianceAt(AnalyticLight::fromDesc(desc), sample, 1.3);
    expectRgbNear(normalized.exact, desc.color * (6.0 / 4.0 * mu * fresnelTransmittance(1.3, mu) / d2), 1e-6);
}

TEST(AnalyticLight, SphereLightIsAPointOfIntensityRadianceTimesCrossSection) {
    hd::LightDesc desc;
    desc.kind = hd::LightKind::Sphere;
    desc.radius = 0.5;
    desc.intensity = 2.0;
    Imath::M44d scaled;
    scaled.setScale(2.0);  // world radius 1
    desc.transform = scaled * translation(0.0, 3.0, 0.0);
    const PlacedSamples below = oneSample({0, 0, 0}, {0, 1, 0});
    const Rgb expected = Rgb(1.0) * (2.0 * std::numbers::pi * 1.0 / 9.0 * fresnelTransmittance(1.3, 1.0));  // L_e pi r^2 / d^2
    expectRgbNear(irradianceAt(AnalyticLight::fromDesc(desc), below, 1.3).exact, expected, 1e-6);
    desc.normalize = true;  // divided by the area 4 pi r^2
    expectRgbNear(irradianceAt(AnalyticLight::fromDesc(desc), below, 1.3).exact, expected / (4.0 * std::numbers::pi), 1e-6);
    // Inside the sphere, and facing away: nothing.
    EXPECT_EQ(irradianceAt(AnalyticLight::fromDesc(desc), oneSample({0, 2.5f, 0}, {0, 1, 0}), 1.3).exact.x, 0.0f);
    EXPECT_EQ(irradianceAt(AnalyticLight::fromDesc(desc), oneSample({0, 0, 0}, {0, -1, 0}), 1.3).exact.x, 0.0f);
}

TEST(AnalyticLight, SpotConeFollowsUsdLuxSmoothstep) {
    hd::LightDesc desc;
    desc.kind = hd::LightKind::Sphere;
    desc.treatAsPoint = true;
    desc.shapingConeAngle = 30.0;
    desc.shapingConeSoftness = 0.5;  // smooth from 15 to 30 degrees
    // Rotation about X by -90 degrees (rows: images of X, Y, Z): the -Z axis points down.
    desc.transform = Imath::M44d(1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 2, 0, 1);
    const AnalyticLight light = AnalyticLight::fromDesc(desc);
    const auto shaped = [&](double offAxisDegrees) {
        const double x = 2.0 * std::tan(offAxisDegrees * std::numbers::pi / 180.0), d2 = x * x + 4.0, mu = 2.0 / std::sqrt(d2);
        const Irradiance e = irradianceAt(light, oneSample({float(x), 0, 0}, {0, 1, 0}), 1.3);
        return e.exact.x / (std::numbers::pi * mu * fresnelTransmittance(1.3, mu) / d2);
    };
    EXPECT_NEAR(shaped(0.0), 1.0, 1e-5);
    EXPECT_NEAR(shaped(10.0), 1.0, 1e-5);
    EXPECT_NEAR(shaped(22.5), 0.5, 1e-4);  // 1 - smoothstep(15, 30, 22.5)
    const double t = (26.0 - 15.0) / 15.0;
    EXPECT_NEAR(shaped(26.0), 1.0 - t * t * (3.0 - 2.0 * t), 1e-4);
    EXPECT_EQ(shaped(35.0), 0.0);
}

TEST(AnalyticLight, DistantLightIntegratesItsDiskUnlessNormalized) {
    hd::LightDesc desc;
    desc.kind = hd::LightKind::Distant;
    desc.intensity = 50000.0;
    desc.angle = 0.53;
    const PlacedSamples facing = oneSample({0, 0, 0}, {0, 0, 1});  // the light shines along -Z
    const double solidAngle = 2.0 * std::numbers::pi * (1.0 - std::cos(0.5 * 0.53 * std::numbers::pi / 180.0));
    const double ft = fresnelTransmittance(1.3, 1.0);
    expectRgbNear(irradianceAt(AnalyticLight::fromDesc(desc), facing, 1.3).exact, Rgb(50000.0 * solidAngle * ft), 1e-6);
    desc.normalize = true;
    expectRgbNear(irradianceAt(AnalyticLight::fromDesc(desc), facing, 1.3).exact, Rgb(50000.0 * ft), 1e-6);
    // 60 degrees off the normal: cos = 1/2.
    const PlacedSamples tilted = oneSample({0, 0, 0}, {float(std::sqrt(3.0) / 2.0), 0.0f, 0.5f});
    expectRgbNear(irradianceAt(AnalyticLight::fromDesc(desc), tilted, 1.3).exact,
                  Rgb(50000.0 * 0.5 * fresnelTransmittance(1.3, 0.5)), 1e-5);
}

TEST(AnalyticLight, OccluderCastsAShadow) {
    RenderMesh blocker;
    blocker.points = {{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}};
    blocker.faceVertexCounts = {4};
    blocker.faceVertexIndices = {0, 1, 2, 3};
    RayScene scene;
    scene.addMesh(blocker, Imath::M44d());
    scene.commit();
    hd::LightDesc desc;
    desc.kind = hd::LightKind::Sphere;
    desc.treatAsPoint = true;
    desc.transform = translation(0.5, 2.0, 0.5);
    const AnalyticLight light = AnalyticLight::fromDesc(desc);
    EXPECT_EQ(irradianceAt(light, oneSample({0.5f, 0, 0.5f}, {0, 1, 0}), 1.3, &scene).exact.x, 0.0f);
    EXPECT_GT(irradianceAt(light, oneSample({0.5f, 0, 0.5f}, {0, 1, 0}), 1.3, nullptr).exact.x, 0.0f);
    EXPECT_GT(irradianceAt(light, oneSample({3.0f, 0, 0.5f}, {0, 1, 0}), 1.3, &scene).exact.x, 0.0f);
}

// UsdLux's colour temperature: the light's colour times a black body of unit luminance.
// Truth: the CIE xy of the irradiance (ACEScg back to XYZ) is the black body's, computed
// from Planck's law and the matching functions; its luminance is the white light's.
TEST(AnalyticLight, ColorTemperatureTintsTheLightAtUnitLuminance) {
    hd::LightDesc desc;
    desc.kind = hd::LightKind::Sphere;
    desc.treatAsPoint = true;
    desc.intensity = 2.0;
    desc.transform = translation(0.0, 3.0, 0.0);
    const PlacedSamples sample = oneSample({0, 0, 0}, {0, 1, 0});
    const Imath::V3f white = irradianceAt(AnalyticLight::fromDesc(desc), sample, 1.3).exact;
    Imath::M33d toXyz;  // ACEScg -> XYZ (D65), the inverse of kXyzD65ToAcescg
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) toXyz[i][j] = kXyzD65ToAcescg[i][j];
    toXyz.invert();
    desc.enableColorTemperature = true;
    for (double kelvin : {1900.0, 2700.0, 6500.0, 12000.0}) {
        desc.colorTemperature = kelvin;
        const Imath::V3f e = irradianceAt(AnalyticLight::fromDesc(desc), sample, 1.3).exact;
        const Imath::V3d rgb(e.x, e.y, e.z);
        const Imath::V3d xyz(toXyz[0][0] * rgb.x + toXyz[0][1] * rgb.y + toXyz[0][2] * rgb.z,
                             toXyz[1][0] * rgb.x + toXyz[1][1] * rgb.y + toXyz[1][2] * rgb.z,
                             toXyz[2][0] * rgb.x + toXyz[2][1] * rgb.y + toXyz[2][2] * rgb.z);
        const double sum = xyz.x + xyz.y + xyz.z;
        const Imath::V2d expected = blackbodyChromaticity(kelvin);
        EXPECT_NEAR(xyz.x / sum, expected.x, 1e-5) << kelvin;
        EXPECT_NEAR(xyz.y / sum, expected.y, 1e-5) << kelvin;
        const double y = kAcescgLuminance.dot(Imath::V3d(e)), whiteY = kAcescgLuminance.dot(Imath::V3d(white));
        EXPECT_NEAR(y, whiteY, 1e-5 * whiteY) << kelvin;
        if (kelvin < 3000.0) {
            EXPECT_GT(e.x, 2.0f * e.z) << "a warm light is red-orange at " << kelvin;
        }
    }
    desc.colorTemperature = 100.0;
    try {
        (void)AnalyticLight::fromDesc(desc);
        FAIL() << "100 K was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("inputs:colorTemperature must be within 500 to 40000 K"), std::string::npos)
            << e.what();
    }
}

TEST(AnalyticLight, RejectsDomesAndNonFiniteParameters) {
    hd::LightDesc desc;
    desc.kind = hd::LightKind::Dome;
    EXPECT_THROW(AnalyticLight::fromDesc(desc), Error);
    desc.kind = hd::LightKind::Sphere;
    desc.intensity = std::nan("");
    EXPECT_THROW(AnalyticLight::fromDesc(desc), Error);
}

}  // namespace
}  // namespace opal
