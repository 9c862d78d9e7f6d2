// The dipole profile against its own integral, and the Fresnel terms against Snell's law
// with the Fresnel amplitude coefficients written out independently here.
#include "schema/error.h"
#include "schema/scatter/dipole.h"
#include "schema/scatter/material.h"
#include "schema/scatter/material_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace opal {
namespace {

constexpr double kPi = std::numbers::pi;

// integral_0^inf R_d(r) 2 pi r dr by composite Simpson in x = ln r (the integrand
// R_d(e^x) 2 pi e^{2x} is smooth in x), from 1e-7 z_r, where the missing disc holds
// ~1e-14 of the total, to 60 decay lengths past the virtual source, where e^{-60} is left.
double integrateProfileNumerically(const DipoleCoefficients& c) {
    const double sigmaT = c.sigmaSPrime + c.sigmaA;
    const double sigmaTr = std::sqrt(3.0 * c.sigmaA * sigmaT);
    const double zr = 1.0 / sigmaT;
    const double xLo = std::log(1e-7 * zr);
    const double xHi = std::log(10.0 * zr + 60.0 / sigmaTr);
    const int intervals = 2000;  // even; h ~ 0.015 in ln r, Simpson error ~ h^4
    const double h = (xHi - xLo) / intervals;
    double sum = 0.0;
    for (int i = 0; i <= intervals; ++i) {
        const double r = std::exp(xLo + i * h);
        const double f = dipoleProfile(r, c) * 2.0 * kPi * r * r;
        sum += f * ((i == 0 || i == intervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0));
    }
    return sum * h / 3.0;
}

double closedForm(const DipoleCoefficients& c) {
    return dipoleTotalReflectance(c.sigmaSPrime / (c.sigmaSPrime + c.sigmaA), c.eta);
}

TEST(Dipole, TotalReflectanceMatchesIntegralForPresets) {
    for (const NamedMaterial& preset : jensenPresets()) {
        for (int ch = 0; ch < 3; ++ch) {
            const DipoleCoefficients c = preset.material.channel(ch);
            EXPECT_NEAR(integrateProfileNumerically(c) / closedForm(c), 1.0, 1e-4) << preset.name << " channel " << ch;
        }
    }
}

TEST(Dipole, TotalReflectanceMatchesIntegralForRandomMaterials) {
    // Wider than any editable range: the identity holds for every medium.
    const EditableRange wide{1e-3, 50.0, 1e-5, 10.0, 1.0, 2.0};
    for (const DipoleCoefficients& c : sampleChannels(wide, 1000, 2024)) {
        EXPECT_NEAR(integrateProfileNumerically(c) / closedForm(c), 1.0, 1e-4)
            << "sigma_s' " << c.sigmaSPrime << " sigma_a " << c.sigmaA << " eta " << c.eta;
    }
}

// integral_0^radius R_d(r) 2 pi r dr by composite Simpson in r (smooth on [0, radius]).
double integrateDiskNumerically(const DipoleCoefficients& c, double radius) {
    const int intervals = 20000;
    const double h = radius / intervals;
    double sum = 0.0;
    for (int i = 0; i <= intervals; ++i) {
        const double r = i * h;
        const double f = dipoleProfile(r, c) * 2.0 * kPi * r;
        sum += f * ((i == 0 || i == intervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0));
    }
    return sum * h / 3.0;
}

TEST(Dipole, DiskReflectanceMatchesIntegralAndTendsToTheTotal) {
    for (const NamedMaterial& preset : jensenPresets())
        for (int ch = 0; ch < 3; ++ch) {
            const DipoleCoefficients c = preset.material.channel(ch);
            for (double radius : {0.01, 0.3, 2.0, 15.0}) {
                const double numeric = integrateDiskNumerically(c, radius);
                EXPECT_NEAR(dipoleDiskReflectance(radius, c), numeric, 1e-7 * closedForm(c) + 1e-9 * numeric)
                    << preset.name << " channel " << ch << " radius " << radius;
            }
            EXPECT_NEAR(dipoleDiskReflectance(std::numeric_limits<double>::infinity(), c), closedForm(c),
                        1e-12 * closedForm(c));
            EXPECT_NEAR(dipoleDiskReflectance(0.0, c), 0.0, 1e-15);
        }
}

TEST(Dipole, ProfileAtOriginMatchesHandExpansion) {
    // r = 0: d = z, so R_d(0) = alpha'/(4 pi) [(sigma_tr + 1/z_r)e^{-sigma_tr z_r}/z_r
    //                                          + (sigma_tr + 1/z_v)e^{-sigma_tr z_v}/z_v].
    const DipoleCoefficients c{1.0, 0.25, 1.4};
    const double sigmaT = 1.25, alpha = 0.8, sigmaTr = std::sqrt(3.0 * 0.25 * 1.25);
    const double fdr = -1.440 / (1.4 * 1.4) + 0.710 / 1.4 + 0.668 + 0.0636 * 1.4;
    const double a = (1.0 + fdr) / (1.0 - fdr);
    const double zr = 1.0 / sigmaT, zv = zr * (1.0 + 4.0 * a / 3.0);
    const double expected = alpha / (4.0 * kPi) *
                            ((sigmaTr + 1.0 / zr) * std::exp(-sigmaTr * zr) / zr +
                             (sigmaTr + 1.0 / zv) * std::exp(-sigmaTr * zv) / zv);
    EXPECT_NEAR(dipoleProfile(0.0, c) / expected, 1.0, 1e-12);
}

// Independent Fresnel reflectance from the angles: r_s = -sin(ti - tt)/sin(ti + tt),
// r_p = tan(ti - tt)/tan(ti + tt) (Born and Wolf), with sin(tt) = sin(ti)/eta.
double fresnelReflectanceFromAngles(double eta, double thetaI) {
    const double thetaT = std::asin(std::sin(thetaI) / eta);
    const double rs = -std::sin(thetaI - thetaT) / std::sin(thetaI + thetaT);
    const double rp = std::tan(thetaI - thetaT) / std::tan(thetaI + thetaT);
    return 0.5 * (rs * rs + rp * rp);
}

TEST(Fresnel, TransmittanceMatchesSnellAndAmplitudeCoefficients) {
    for (double eta : {1.1, 1.3, 1.5, 2.0}) {
        for (double degrees : {5.0, 20.0, 45.0, 60.0, 75.0, 85.0, 89.0}) {
            const double thetaI = degrees * kPi / 180.0;
            EXPECT_NEAR(fresnelTransmittance(eta, std::cos(thetaI)), 1.0 - fresnelReflectanceFromAngles(eta, thetaI),
                        1e-12)
                << "eta " << eta << " angle " << degrees;
        }
    }
}

TEST(Fresnel, NormalIncidenceAndGrazing) {
    for (double eta : {1.2, 1.5}) {
        const double r0 = (eta - 1.0) / (eta + 1.0);
        EXPECT_NEAR(fresnelTransmittance(eta, 1.0), 1.0 - r0 * r0, 1e-15);
        EXPECT_NEAR(fresnelTransmittance(eta, 0.0), 0.0, 1e-15);
    }
}

TEST(Fresnel, IndexMatchedBoundaryTransmitsEverything) {
    for (double cosTheta : {0.0, 0.3, 1.0}) EXPECT_EQ(fresnelTransmittance(1.0, cosTheta), 1.0);
}

TEST(Fresnel, CosineIsClampedAndBadInputThrows) {
    EXPECT_EQ(fresnelTransmittance(1.3, 1.5), fresnelTransmittance(1.3, 1.0));
    EXPECT_EQ(fresnelTransmittance(1.3, -0.5), fresnelTransmittance(1.3, 0.0));
    EXPECT_THROW(fresnelTransmittance(1.3, std::nan("")), Error);
    EXPECT_THROW(fresnelTransmittance(0.0, 0.5), Error);
    EXPECT_THROW(fresnelTransmittance(std::nan(""), 0.5), Error);
}

TEST(Fresnel, TotalInternalReflectionBelowCriticalAngle) {
    // From inside a denser medium (relative index 1/1.5), beyond the critical angle.
    const double eta = 1.0 / 1.5;
    const double critical = std::asin(eta);
    EXPECT_EQ(fresnelTransmittance(eta, std::cos(critical + 0.05)), 0.0);
    const double thetaI = critical - 0.2;
    EXPECT_NEAR(fresnelTransmittance(eta, std::cos(thetaI)), 1.0 - fresnelReflectanceFromAngles(eta, thetaI), 1e-12);
}

TEST(Fresnel, DiffuseReflectanceFitMatchesHemisphericalIntegral) {
    // F_dr is the internal diffuse reflectance: light inside hitting the boundary. By
    // reciprocity F_dr = 1 - (1 - F_dr,external) / eta^2 with the external one
    // integral_0^{pi/2} F_r(eta, theta) 2 cos(theta) sin(theta) dtheta (midpoint rule).
    for (double eta : {1.2, 1.3, 1.4, 1.6}) {
        const int n = 20000;
        double external = 0.0;
        for (int i = 0; i < n; ++i) {
            const double theta = (i + 0.5) * (kPi / 2) / n;
            external += fresnelReflectanceFromAngles(eta, theta) * 2.0 * std::cos(theta) * std::sin(theta) * (kPi / 2) / n;
        }
        const double internal = 1.0 - (1.0 - external) / (eta * eta);
        // Egan and Hilgeman's fit is good to about 1% in this range.
        EXPECT_NEAR(fresnelDiffuseReflectance(eta), internal, 0.01 * internal) << "eta " << eta;
    }
}

}  // namespace
}  // namespace opal
