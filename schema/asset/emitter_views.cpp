#include "schema/asset/emitter_views.h"

#include "schema/asset/cube_map.h"

#include <algorithm>
#include <cmath>

namespace opal {
namespace {

// Bilinear position on a grid of n cells over [-1, 1]: the lower cell, the next, the weight.
struct Lerp {
    std::uint32_t i0 = 0, i1 = 0;
    float f = 0.0f;
};

Lerp lerpAt(double c, std::uint32_t n) {
    const double x = std::clamp((c + 1.0) * 0.5 * n - 0.5, 0.0, double(n - 1));
    Lerp l;
    l.i0 = std::uint32_t(x);
    l.i1 = std::min(l.i0 + 1, n - 1);
    l.f = float(x - l.i0);
    return l;
}

Imath::V3f pixel(const EmitterViews& v, std::uint32_t view, std::uint32_t i, std::uint32_t j) {
    const std::size_t at = 3 * ((std::size_t(view) * v.imageSize + j) * v.imageSize + i);
    return {v.radiance[at], v.radiance[at + 1], v.radiance[at + 2]};
}

Imath::V3f imageAt(const EmitterViews& v, std::uint32_t view, const Imath::V3d& direction, double radius,
                   const Imath::V3d& b) {
    Imath::V3d right, up;
    viewAxes(direction, right, up);
    const Lerp x = lerpAt(b.dot(right) / radius, v.imageSize), y = lerpAt(b.dot(up) / radius, v.imageSize);
    const auto row = [&](std::uint32_t j) {
        return pixel(v, view, x.i0, j) * (1.0f - x.f) + pixel(v, view, x.i1, j) * x.f;
    };
    return row(y.i0) * (1.0f - y.f) + row(y.i1) * y.f;
}

}  // namespace

void viewAxes(const Imath::V3d& v, Imath::V3d& right, Imath::V3d& up) {
    const Imath::V3d up0 = std::abs(v.y) > 0.999 ? Imath::V3d(0.0, 0.0, 1.0) : Imath::V3d(0.0, 1.0, 0.0);
    right = up0.cross(v).normalized();
    up = v.cross(right);
}

Imath::V3f viewedRadiance(const EmitterViews& views, double radius, const Imath::V3d& d, const Imath::V3d& b) {
    if (views.empty() || !(b.length2() < radius * radius)) return Imath::V3f(0.0f);
    const CubeMapLayout layout(views.directionFaceSize);
    const CubeFacePoint p = CubeMapLayout::facePoint(Imath::V3f(-d));
    const std::uint32_t n = views.directionFaceSize;
    const Lerp s = lerpAt(p.s, n), t = lerpAt(p.t, n);
    Imath::V3f sum(0.0f);
    const auto add = [&](std::uint32_t u, std::uint32_t v, float w) {
        if (w <= 0.0f) return;
        const std::uint32_t view = layout.index({p.face, u, v});
        sum += imageAt(views, view, Imath::V3d(layout.direction(view)), radius, b) * w;
    };
    add(s.i0, t.i0, (1.0f - s.f) * (1.0f - t.f));
    add(s.i1, t.i0, s.f * (1.0f - t.f));
    add(s.i0, t.i1, (1.0f - s.f) * t.f);
    add(s.i1, t.i1, s.f * t.f);
    return sum;
}

}  // namespace opal
