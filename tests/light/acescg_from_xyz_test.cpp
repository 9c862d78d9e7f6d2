// The XYZ -> ACEScg matrices against the ACEScg definition (Academy S-2014-004 primaries
// and white) and against OpenColorIO's own ACEScg <-> CIE XYZ (D65) Bradford transform,
// and the black-body colours the light bake emits against the same transform.
#include "schema/scatter/acescg_from_xyz.h"
#include "schema/scatter/blackbody.h"

#include <Imath/ImathMatrix.h>
#include <OpenColorIO/OpenColorIO.h>
#include <gtest/gtest.h>

#include <array>

namespace opal {
namespace {

namespace OCIO = OCIO_NAMESPACE;

constexpr Imath::V2d kAcesWhite{0.32168, 0.33767};
constexpr Imath::V2d kD65{0.3127, 0.3290};

Imath::V3d xyzOf(const Imath::V2d& xy) { return {xy.x / xy.y, 1.0, (1.0 - xy.x - xy.y) / xy.y}; }

Imath::V2d chromaticityOf(const Imath::V3d& xyz) {
    const double sum = xyz.x + xyz.y + xyz.z;
    return {xyz.x / sum, xyz.y / sum};
}

Imath::M33d matrixOf(const ColorMatrix& m) {
    return Imath::M33d(m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1], m[2][2]);
}

// Imath multiplies row vectors; m's rows act on column vectors.
Imath::V3d applied(const Imath::M33d& m, const Imath::V3d& v) {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

void expectNear(const Imath::V3d& actual, const Imath::V3d& expected, double tolerance) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], expected[c], tolerance) << "channel " << c;
}

TEST(AcescgFromXyz, MapsTheAcesWhiteToNeutral) {
    expectNear(transform(kXyzToAp1, xyzOf(kAcesWhite)), {1, 1, 1}, 1e-8);
}

TEST(AcescgFromXyz, PrimariesAreAp1s) {
    const Imath::M33d ap1ToXyz = matrixOf(kXyzToAp1).gjInverse();
    const std::array<Imath::V2d, 3> primaries = {{{0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044}}};
    for (int p = 0; p < 3; ++p) {
        Imath::V3d unit(0.0);
        unit[p] = 1.0;
        const Imath::V2d xy = chromaticityOf(applied(ap1ToXyz, unit));
        EXPECT_NEAR(xy.x, primaries[p].x, 1e-8) << "primary " << p;
        EXPECT_NEAR(xy.y, primaries[p].y, 1e-8) << "primary " << p;
    }
    // Luminance is the Y row of AP1 -> XYZ.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(ap1ToXyz[1][c], kAcescgLuminance[c], 1e-8) << c;
}

TEST(AcescgFromXyz, AdaptsD65ToNeutral) {
    expectNear(transform(kBradfordD65ToAcesWhite, xyzOf(kD65)), xyzOf(kAcesWhite), 1e-8);
    expectNear(transform(kXyzD65ToAcescg, xyzOf(kD65)), {1, 1, 1}, 1e-8);
}

// OCIO's builtin ACEScg -> CIE XYZ (D65, Bradford), run in float.
Imath::V3d ocioAcescgToXyzD65(const Imath::V3d& rgb) {
    const OCIO::BuiltinTransformRcPtr builtin = OCIO::BuiltinTransform::Create();
    builtin->setStyle("UTILITY - ACES-AP1_to_CIE-XYZ-D65_BFD");
    const OCIO::ConstCPUProcessorRcPtr cpu =
        OCIO::Config::CreateRaw()->getProcessor(builtin)->getDefaultCPUProcessor();
    std::array<float, 3> v{float(rgb.x), float(rgb.y), float(rgb.z)};
    cpu->applyRGB(v.data());
    return {v[0], v[1], v[2]};
}

TEST(AcescgFromXyz, InvertsOpenColorIOsAcescgToXyzD65) {
    for (const Imath::V3d& xyz : {Imath::V3d(1, 0, 0), Imath::V3d(0, 1, 0), Imath::V3d(0, 0, 1),
                                  Imath::V3d(0.4, 0.35, 0.1)}) {
        expectNear(ocioAcescgToXyzD65(transform(kXyzD65ToAcescg, xyz)), xyz, 1e-5);
    }
}

// Back to XYZ with OpenColorIO, a black body's colour has the black body's chromaticity:
// it is ACEScg, not another space's RGB.
TEST(AcescgFromXyz, BlackbodyRoundTripsToItsChromaticity) {
    for (double k : {1000.0, 1700.0, 3000.0, 6500.0, 20000.0}) {
        const Imath::V2d xy = chromaticityOf(ocioAcescgToXyzD65(blackbodyAcescg(k)));
        const Imath::V2d expected = blackbodyChromaticity(k);
        EXPECT_NEAR(xy.x, expected.x, 1e-5) << k << " K";
        EXPECT_NEAR(xy.y, expected.y, 1e-5) << k << " K";
    }
}

}  // namespace
}  // namespace opal
