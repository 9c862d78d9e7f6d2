#include "delegate/relight/analytic_light.h"

#include "delegate/relight/fresnel_response.h"
#include "delegate/relight/light_emission.h"
#include "raytrace/ray_scene.h"
#include "schema/error.h"
#include "schema/scatter/dipole.h"
#include "schema/scatter/fresnel_moments.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace opal {

namespace {

constexpr double kPi = std::numbers::pi;

double radians(double degrees) { return degrees * kPi / 180.0; }

double smoothstep(double edge0, double edge1, double x) {
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// The mean length of the transform's axes: the light's scale for its radius.
double axisScale(const Imath::M44d& m) {
    double sum = 0.0;
    for (int r = 0; r < 3; ++r) sum += Imath::V3d(m[r][0], m[r][1], m[r][2]).length();
    return sum / 3.0;
}

void requireFinite(const hd::LightDesc& d) {
    const bool ok = std::isfinite(d.radius) && d.radius >= 0.0 && std::isfinite(d.angle) && d.angle >= 0.0 &&
                    (!d.shapingConeAngle || std::isfinite(*d.shapingConeAngle)) &&
                    std::isfinite(d.shapingConeSoftness);
    if (!ok) throw Error("analytic light: radius, angle and shaping must be finite (radius and angle non-negative)");
}

}  // namespace

AnalyticLight AnalyticLight::fromDesc(const hd::LightDesc& desc) {
    if (desc.kind != hd::LightKind::Sphere && desc.kind != hd::LightKind::Distant)
        throw Error("analytic light: only sphere (point, spot) and distant lights are analytic");
    requireFinite(desc);
    AnalyticLight light;
    Imath::V3d axis;
    desc.transform.multDirMatrix(Imath::V3d(0.0, 0.0, -1.0), axis);
    if (!(axis.length() > 0.0)) throw Error("analytic light: the transform is singular");
    light.axis_ = axis.normalized();
    const Rgb le = emittedRadiance(desc);
    if (desc.kind == hd::LightKind::Distant) {
        light.kind_ = Kind::Distant;
        const double halfAngle = 0.5 * radians(desc.angle);
        const double solidAngle = 2.0 * kPi * (1.0 - std::cos(halfAngle));
        light.power_ = (desc.normalize || solidAngle == 0.0) ? le : le * solidAngle;
        return light;
    }
    light.kind_ = Kind::Point;
    desc.transform.multVecMatrix(Imath::V3d(0.0), light.position_);
    light.radius_ = desc.treatAsPoint ? 0.0 : desc.radius * axisScale(desc.transform);
    if (light.radius_ > 0.0) {
        const double r2 = light.radius_ * light.radius_;
        light.power_ = le * (kPi * r2) / (desc.normalize ? 4.0 * kPi * r2 : 1.0);  // I = L_e pi r^2
    } else {
        light.power_ = desc.normalize ? le / 4.0 : le * kPi;
    }
    if (desc.shapingConeAngle) {
        const double cutoff = radians(std::clamp(*desc.shapingConeAngle, 0.0, 180.0));
        const double softness = std::clamp(desc.shapingConeSoftness, 0.0, 1.0);
        light.cone_ = Cone{cutoff, (1.0 - softness) * cutoff};
    }
    return light;
}

// UsdLux ShapingAPI: 1 - smoothstep(theta_start, theta_cut, theta_off); a step when soft = 0.
double AnalyticLight::shaping(const Imath::V3d& emission) const {
    if (!cone_) return 1.0;
    const double off = std::acos(std::clamp(emission.dot(axis_), -1.0, 1.0));
    if (off > cone_->cutoff) return 0.0;
    if (cone_->smoothStart >= cone_->cutoff) return 1.0;
    return 1.0 - smoothstep(cone_->smoothStart, cone_->cutoff, off);
}

std::optional<Incidence> AnalyticLight::incidence(const Imath::V3d& point) const {
    if (kind_ == Kind::Distant)
        return Incidence{-axis_, power_, std::numeric_limits<double>::infinity()};
    const Imath::V3d toLight = position_ - point;
    const double d = toLight.length();
    if (!(d > radius_)) return std::nullopt;  // inside the emitting sphere (or at the point)
    const Imath::V3d direction = toLight / d;
    const double shape = shaping(-direction);
    if (shape <= 0.0) return std::nullopt;
    // E_perp = I / d^2, saturated (light_emission.h): unbounded as a point light nears the point.
    Rgb e = power_ * (shape / (d * d));
    for (int c = 0; c < 3; ++c) e[c] = std::min(e[c], kMaxSampleIrradiance);
    return Incidence{direction, e, d - radius_};
}

std::vector<LightArrival> lightArrivals(const AnalyticLight& light, const PlacedSamples& samples,
                                        const RayScene* scene, float offset) {
    const std::size_t n = samples.positions.size();
    std::vector<LightArrival> arrivals(n);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 512), [&](const tbb::blocked_range<std::size_t>& range) {
        std::vector<Ray> rays;
        std::vector<std::size_t> owner;
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
            const std::optional<Incidence> in = light.incidence(Imath::V3d(samples.positions[i]));
            if (!in) continue;
            const float mu = float(Imath::V3d(samples.normals[i]).dot(in->toLight));
            if (mu <= 0.0f) continue;
            arrivals[i] = {mu, Imath::V3f(float(in->normalIrradiance.x), float(in->normalIrradiance.y),
                                          float(in->normalIrradiance.z))};
            if (!scene) continue;
            const Imath::V3f origin = samples.positions[i] + samples.normals[i] * offset;
            const float far = std::isinf(in->distance) ? std::numeric_limits<float>::infinity()
                                                       : float(in->distance) * (1.0f - 1e-4f);
            rays.push_back({origin, Imath::V3f(in->toLight), 0.0f, far});
            owner.push_back(i);
        }
        std::vector<std::uint8_t> blocked(rays.size());
        if (scene) scene->occluded(rays, blocked);
        for (std::size_t r = 0; r < rays.size(); ++r)
            if (blocked[r]) arrivals[owner[r]] = {};
    });
    return arrivals;
}

void addMoments(std::span<const LightArrival> arrivals, const FresnelResponse& response,
                IrradianceMoments& moments) {
    if (arrivals.size() != moments.samples || int(moments.terms) != response.terms())
        throw Error("irradiance: light arrivals and moments disagree in samples or terms");
    float h[kMaxFresnelTerms];
    for (std::size_t i = 0; i < arrivals.size(); ++i) {
        const LightArrival& a = arrivals[i];
        if (a.cosTheta <= 0.0f) continue;
        response.evaluate(a.cosTheta, h);
        float* e = moments.sample(i);
        for (std::uint32_t m = 0; m < moments.terms; ++m) {
            const float w = a.cosTheta * h[m];  // E_m = E_perp mu h_m(mu)
            e[3 * m + 0] += w * a.irradiance.x;
            e[3 * m + 1] += w * a.irradiance.y;
            e[3 * m + 2] += w * a.irradiance.z;
        }
    }
}

void addExactIrradiance(std::span<const LightArrival> arrivals, double eta, std::span<float> rgb) {
    if (rgb.size() != 3 * arrivals.size()) throw Error("irradiance: exact irradiance needs samples x 3 values");
    for (std::size_t i = 0; i < arrivals.size(); ++i) {
        const LightArrival& a = arrivals[i];
        if (a.cosTheta <= 0.0f) continue;
        const float w = a.cosTheta * float(fresnelTransmittance(eta, a.cosTheta));  // F_t(eta, mu) mu
        rgb[3 * i + 0] += w * a.irradiance.x;
        rgb[3 * i + 1] += w * a.irradiance.y;
        rgb[3 * i + 2] += w * a.irradiance.z;
    }
}

}  // namespace opal
