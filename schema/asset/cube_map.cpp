#include "schema/asset/cube_map.h"

#include "schema/error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace opal {

namespace {

// Integral of the solid-angle density 1/(1+s^2+t^2)^{3/2} from (0,0) to (s,t) on a face at
// unit distance.
double solidAngleTo(double s, double t) { return std::atan2(s * t, std::sqrt(s * s + t * t + 1.0)); }

double faceCoordinate(std::uint32_t i, std::uint32_t size) { return 2.0 * (i + 0.5) / size - 1.0; }

}  // namespace

CubeMapLayout::CubeMapLayout(std::uint32_t faceSize) : size_(faceSize) {
    if (faceSize == 0 || (faceSize & (faceSize - 1)) != 0 || faceSize > kMaxFaceSize)
        throw Error("cube map: face size must be a power of two up to " + std::to_string(kMaxFaceSize) + ", got " +
                    std::to_string(faceSize));
}

ChartLayout CubeMapLayout::charts() const {
    std::uint32_t log2 = 0;
    while ((1u << log2) < size_) ++log2;
    return ChartLayout{6, log2};
}

CubeMapTexel CubeMapLayout::texel(std::uint32_t index) const {
    return {index / (size_ * size_), index % size_, (index / size_) % size_};
}

// OpenGL cube-map convention, inverted: a face and (s, t) in [-1, 1]^2 give a direction.
Imath::V3f CubeMapLayout::faceDirection(std::uint32_t face, float s, float t) {
    Imath::V3f d;
    switch (face) {
        case 0: d = {1.0f, -t, -s}; break;
        case 1: d = {-1.0f, -t, s}; break;
        case 2: d = {s, 1.0f, t}; break;
        case 3: d = {s, -1.0f, -t}; break;
        case 4: d = {s, -t, 1.0f}; break;
        default: d = {-s, -t, -1.0f}; break;
    }
    return d.normalized();
}

Imath::V3f CubeMapLayout::direction(std::uint32_t index) const {
    const CubeMapTexel t = texel(index);
    return faceDirection(t.face, float(faceCoordinate(t.u, size_)), float(faceCoordinate(t.v, size_)));
}

CubeFacePoint CubeMapLayout::facePoint(const Imath::V3f& d) {
    const float ax = std::fabs(d.x), ay = std::fabs(d.y), az = std::fabs(d.z);
    std::uint32_t face;
    float sc, tc, ma;
    if (ax >= ay && ax >= az) {
        face = d.x >= 0 ? 0 : 1;
        sc = d.x >= 0 ? -d.z : d.z;
        tc = -d.y;
        ma = ax;
    } else if (ay >= az) {
        face = d.y >= 0 ? 2 : 3;
        sc = d.x;
        tc = d.y >= 0 ? d.z : -d.z;
        ma = ay;
    } else {
        face = d.z >= 0 ? 4 : 5;
        sc = d.z >= 0 ? d.x : -d.x;
        tc = -d.y;
        ma = az;
    }
    if (!(ma > 0.0f)) return {};  // zero or NaN direction: a defined point, never out of range
    const auto coordinate = [&](float c) { return std::isfinite(c / ma) ? std::clamp(c / ma, -1.0f, 1.0f) : 0.0f; };
    return {face, coordinate(sc), coordinate(tc)};
}

std::uint32_t CubeMapLayout::lookup(const Imath::V3f& d) const {
    const CubeFacePoint p = facePoint(d);
    const auto toTexel = [&](float c) {
        const float x = (c + 1.0f) * 0.5f * float(size_);
        return std::uint32_t(std::clamp(x, 0.0f, float(size_) - 1.0f));
    };
    return index({p.face, toTexel(p.s), toTexel(p.t)});
}

double CubeMapLayout::solidAngle(std::uint32_t index) const {
    const CubeMapTexel t = texel(index);
    const double s0 = 2.0 * t.u / size_ - 1.0, s1 = 2.0 * (t.u + 1) / size_ - 1.0;
    const double t0 = 2.0 * t.v / size_ - 1.0, t1 = 2.0 * (t.v + 1) / size_ - 1.0;
    return solidAngleTo(s1, t1) - solidAngleTo(s0, t1) - solidAngleTo(s1, t0) + solidAngleTo(s0, t0);
}

}  // namespace opal
