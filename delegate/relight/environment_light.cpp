#include "delegate/relight/environment_light.h"

#include "delegate/relight/light_emission.h"

#include "schema/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace opal {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kSupersamples = 2;  // per axis and cube-map texel

}  // namespace

LatLongMap::LatLongMap(int width, int height, std::vector<float> rgb) {
    if (width <= 0 || height <= 0 || rgb.size() != std::size_t(width) * std::size_t(height) * 3)
        throw Error("lat-long map: " + std::to_string(rgb.size()) + " floats do not make a " + std::to_string(width) +
                    " x " + std::to_string(height) + " RGB image");
    for (std::size_t i = 0; i < rgb.size(); ++i) {
        if (!(rgb[i] >= 0.0f && rgb[i] <= kMaxEmittedRadiance))
            throw Error("lat-long map: pixel " + std::to_string(i / 3 % std::size_t(width)) + ", " +
                        std::to_string(i / 3 / std::size_t(width)) + " is " + std::to_string(rgb[i]) +
                        ": not finite, negative or above 1e20");
        maxValue_ = std::max(maxValue_, rgb[i]);
    }
    levels_.push_back({width, height, std::move(rgb)});
    while (levels_.back().height > 1 || levels_.back().width > 1) levels_.push_back(halve(levels_.back()));
}

// One pyramid step: every coarse pixel is the mean of the (up to) 2 x 2 fine pixels under it.
LatLongMap::Level LatLongMap::halve(const Level& fine) {
    Level coarse{std::max(1, (fine.width + 1) / 2), std::max(1, (fine.height + 1) / 2), {}};
    coarse.rgb.assign(std::size_t(coarse.width) * coarse.height * 3, 0.0f);
    for (int y = 0; y < coarse.height; ++y)
        for (int x = 0; x < coarse.width; ++x) {
            float sum[3] = {0.0f, 0.0f, 0.0f};
            int count = 0;
            for (int fy = 2 * y; fy < std::min(2 * y + 2, fine.height); ++fy)
                for (int fx = 2 * x; fx < std::min(2 * x + 2, fine.width); ++fx, ++count)
                    for (int c = 0; c < 3; ++c) sum[c] += fine.rgb[(std::size_t(fy) * fine.width + fx) * 3 + c];
            for (int c = 0; c < 3; ++c) coarse.rgb[(std::size_t(y) * coarse.width + x) * 3 + c] = sum[c] / float(count);
        }
    return coarse;
}

// phi = pi (1 - 2u), theta = pi (1/2 - v); d = (cos theta sin phi, sin theta, cos theta cos phi).
Imath::V3d LatLongMap::direction(double u, double v) {
    const double phi = kPi * (1.0 - 2.0 * u), theta = kPi * (0.5 - v);
    return {std::cos(theta) * std::sin(phi), std::sin(theta), std::cos(theta) * std::cos(phi)};
}

Imath::V2d LatLongMap::coordinates(const Imath::V3d& d) {
    const double length = d.length();
    const double theta = std::asin(std::clamp(d.y / length, -1.0, 1.0));
    const double phi = std::atan2(d.x, d.z);
    return {0.5 * (1.0 - phi / kPi), 0.5 - theta / kPi};
}

// Bilinear between pixel centres; wraps around in longitude, clamps at the poles. Float
// arithmetic (u in [0, 1] resolves 2^-24 of a row, far below a pixel of any map), and
// floor(t) as int(t + 1) - 1, exact for t > -1, which u and v in [0, 1] guarantee: the
// baseline x86-64 build has no rounding instruction, and std::floor was a third of a
// lookup.
Imath::V3f LatLongMap::bilinear(const Level& level, float u, float v) {
    u = std::clamp(u, 0.0f, 1.0f), v = std::clamp(v, 0.0f, 1.0f);
    const float x = u * float(level.width) + 0.5f, y = v * float(level.height) + 0.5f;  // t + 1, t = x - 1/2
    const int xi = int(x), yi = int(y);
    const float fx = x - float(xi), fy = y - float(yi);
    int xa = xi - 1, xb = xi;  // in [-1, width]: wrap once
    if (xa < 0) xa += level.width;
    if (xb >= level.width) xb -= level.width;
    const int ya = std::clamp(yi - 1, 0, level.height - 1), yb = std::min(yi, level.height - 1);
    const float* rowA = level.rgb.data() + std::size_t(ya) * level.width * 3;
    const float* rowB = level.rgb.data() + std::size_t(yb) * level.width * 3;
    Imath::V3f sum;  // as a + (b - a) f, so that equal neighbours come back exactly
    for (int c = 0; c < 3; ++c) {
        const float top = rowA[3 * xa + c] + (rowA[3 * xb + c] - rowA[3 * xa + c]) * fx;
        const float bottom = rowB[3 * xa + c] + (rowB[3 * xb + c] - rowB[3 * xa + c]) * fx;
        sum[c] = top + (bottom - top) * fy;
    }
    return sum;
}

// Level l has pixels pi 2^l / H tall: the finest level with pixels >= footprint / 2, so
// bilinear taps `footprint` apart still see every pixel.
int LatLongMap::levelFor(double footprint) const {
    const double ratio = footprint * height() / kPi;
    return ratio >= 2.0 ? std::min(std::ilogb(ratio), int(levels_.size()) - 1) : 0;
}

Imath::V3f LatLongMap::sample(double u, double v, double footprint) const {
    return sampleLevel(levelFor(footprint), float(u), float(v));
}

EnvironmentLight::EnvironmentLight(std::shared_ptr<const LatLongMap> map, const Imath::M44d& domeToWorld,
                                   const Rgb& scale)
    : map_(std::move(map)), domeFromWorld_(rotationOf(domeToWorld, "dome light").transposed()), scale_(scale) {
    if (!map_) throw Error("dome light: no lat-long map");
    const double brightest = std::max({scale.x, scale.y, scale.z}) * double(map_->maxValue());
    if (!(std::min({scale.x, scale.y, scale.z}) >= 0.0) || !(brightest <= kMaxEmittedRadiance))
        throw Error("dome light: color * intensity * 2^exposure (" + std::to_string(scale.x) + ", " +
                    std::to_string(scale.y) + ", " + std::to_string(scale.z) + ") times the map's brightest texel " +
                    std::to_string(map_->maxValue()) + " must be non-negative and at most 1e20");
}

EnvironmentLight EnvironmentLight::fromDesc(std::shared_ptr<const LatLongMap> map, const hd::LightDesc& desc) {
    if (desc.kind != hd::LightKind::Dome) throw Error("dome light: the description is not a dome light");
    return EnvironmentLight(std::move(map), desc.transform, emittedRadiance(desc));
}

Imath::M33d EnvironmentLight::domeFromObject(const Imath::M44d& objectToWorld) const {
    // Object -> world -> dome, row vectors.
    return rotationOf(objectToWorld, "dome light: mesh") * domeFromWorld_;
}

std::vector<float> EnvironmentLight::cubeRadiance(const CubeMapLayout& cube, const Imath::M44d& objectToWorld) const {
    return cubeRadianceIn(cube, domeFromObject(objectToWorld), scale_);
}

std::vector<float> EnvironmentLight::domeCubeMap(const CubeMapLayout& cube) const {
    return cubeRadianceIn(cube, Imath::M33d(), Rgb(1.0));
}

std::vector<float> EnvironmentLight::cubeRadianceIn(const CubeMapLayout& cube, const Imath::M33d& domeFromCube,
                                                    const Rgb& scale) const {
    const std::uint32_t size = cube.faceSize();
    std::vector<float> radiance(std::size_t(cube.texels()) * 3);
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, cube.texels(), 64), [&](const auto& range) {
        for (std::uint32_t index = range.begin(); index != range.end(); ++index) {
            const CubeMapTexel texel = cube.texel(index);
            const double footprint = std::sqrt(cube.solidAngle(index)) / kSupersamples;
            Imath::V3d sum(0.0);
            double weights = 0.0;
            for (int a = 0; a < kSupersamples; ++a)
                for (int b = 0; b < kSupersamples; ++b) {
                    const double s = 2.0 * (texel.u + (a + 0.5) / kSupersamples) / size - 1.0;
                    const double t = 2.0 * (texel.v + (b + 0.5) / kSupersamples) / size - 1.0;
                    const double q = 1.0 + s * s + t * t;
                    const double w = 1.0 / (q * std::sqrt(q));  // solid angle per unit face area
                    const Imath::V3d d = Imath::V3d(CubeMapLayout::faceDirection(texel.face, float(s), float(t))) * domeFromCube;
                    const Imath::V2d uv = LatLongMap::coordinates(d);
                    sum += Imath::V3d(map_->sample(uv.x, uv.y, footprint)) * w;
                    weights += w;
                }
            for (int c = 0; c < 3; ++c) radiance[std::size_t(index) * 3 + c] = float(sum[c] / weights * scale[c]);
        }
    });
    return radiance;
}

}  // namespace opal
