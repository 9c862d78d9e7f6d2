#include "bake/light/direct_irradiance.h"

#include "schema/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace opal {

Imath::V3d directIrradiance(const EmitterScene& emitter, const RayScene* blockers, const Imath::V3d& at,
                            const Imath::V3d& x, const Imath::V3d& n, double offset, int side) {
    constexpr double kPi = std::numbers::pi;
    const BoundingSphere& b = emitter.bounds();
    const Imath::V3d p = x - at, toCentre = b.centre - p;
    const double d = toCentre.length();
    // The cone of directions that can reach the emitter's bounding sphere; from inside it,
    // every direction (cosMax = -1).
    const double cosMax = d > b.radius ? std::sqrt(1.0 - (b.radius / d) * (b.radius / d)) : -1.0;
    const Imath::V3d axis = d > 0.0 ? toCentre / d : Imath::V3d(0, 0, 1);
    const Imath::V3d e1 = (std::abs(axis.x) < 0.9 ? Imath::V3d(1, 0, 0) : Imath::V3d(0, 1, 0)).cross(axis).normalized();
    const Imath::V3d e2 = axis.cross(e1);
    const double solidAngle = 2.0 * kPi * (1.0 - cosMax);
    const Imath::V3f origin(x + n * offset);
    Imath::V3d e(0.0);
    for (int i = 0; i < side; ++i)
        for (int j = 0; j < side; ++j) {
            const double cosTheta = 1.0 - (i + 0.5) / side * (1.0 - cosMax), phi = 2.0 * kPi * (j + 0.5) / side;
            const double sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
            const Imath::V3d w = axis * cosTheta + (e1 * std::cos(phi) + e2 * std::sin(phi)) * sinTheta;
            const double mu = n.dot(w);
            if (mu <= 0.0) continue;
            const Ray ray(Imath::V3f(p), Imath::V3f(w), 0.0f, 1e30f);
            const std::optional<RayHit> hit = emitter.rays().intersect(ray);
            const Imath::V3f l = emitter.radiance(ray, hit);
            if (!hit || l.x + l.y + l.z <= 0.0f) continue;
            if (blockers && blockers->occluded(Ray(origin, Imath::V3f(w), 0.0f, hit->t))) continue;
            e += Imath::V3d(l) * mu;
        }
    return e * (solidAngle / (double(side) * side));
}

double relativeRmse(std::span<const Imath::V3d> estimate, std::span<const Imath::V3d> direct) {
    if (estimate.size() != direct.size())
        throw Error("relative RMSE: " + std::to_string(estimate.size()) + " estimates of E for " +
                    std::to_string(direct.size()) + " directly integrated values");
    double error = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < direct.size(); ++i) {
        error += (estimate[i] - direct[i]).length2();
        norm += direct[i].length2();
    }
    if (norm > 0.0) return std::sqrt(error / norm);
    return error > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;  // light where there is none
}

}  // namespace opal
