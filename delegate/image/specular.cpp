#include "delegate/image/specular.h"

#include "schema/scatter/dipole.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace opal {

double fresnelReflectance(double eta, double cosTheta) {
    return 1.0 - fresnelTransmittance(eta, std::clamp(cosTheta, 0.0, 1.0));
}

double ggxAlpha(double roughness) {
    const double r = std::clamp(roughness, 0.0, 1.0);
    return std::max(r * r, 1e-4);
}

double ggxDistribution(double nDotH, double alpha) {
    if (nDotH <= 0.0) return 0.0;
    const double a2 = alpha * alpha;
    const double d = nDotH * nDotH * (a2 - 1.0) + 1.0;
    return a2 / (std::numbers::pi * d * d);
}

namespace {

// f_s(l, v) (n.l) with F_r from `reflectance(cos theta)`.
template <typename Reflectance>
double ggx(const Imath::V3d& n, const Imath::V3d& v, const Imath::V3d& l, double alpha, const Reflectance& reflectance) {
    const double nl = n.dot(l), nv = n.dot(v);
    if (nl <= 0.0 || nv <= 0.0) return 0.0;
    Imath::V3d h = l + v;
    const double length = h.length();
    if (!(length > 0.0)) return 0.0;
    h /= length;
    const double a2 = alpha * alpha;
    // Smith height-correlated masking-shadowing, folded with 1 / (4 n.l n.v).
    const double visibility =
        0.5 / (nl * std::sqrt(nv * nv * (1.0 - a2) + a2) + nv * std::sqrt(nl * nl * (1.0 - a2) + a2));
    return ggxDistribution(n.dot(h), alpha) * visibility * reflectance(v.dot(h)) * nl;
}

}  // namespace

double ggxReflectance(const Imath::V3d& n, const Imath::V3d& v, const Imath::V3d& l, double alpha, double eta) {
    return ggx(n, v, l, alpha, [eta](double c) { return fresnelReflectance(eta, c); });
}

double ggxReflectance(const Imath::V3d& n, const Imath::V3d& v, const Imath::V3d& l, double alpha,
                      const FresnelTable& fresnel) {
    return ggx(n, v, l, alpha, [&fresnel](double c) { return 1.0 - fresnel.transmittance(c); });
}

Imath::V3d reflect(const Imath::V3d& v, const Imath::V3d& n) { return n * (2.0 * n.dot(v)) - v; }

double reflectionFootprint(double alpha) { return std::min(2.0 * alpha, std::numbers::pi); }

}  // namespace opal
