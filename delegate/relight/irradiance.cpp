#include "delegate/relight/irradiance.h"

#include "schema/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <string>

namespace opal {

IrradianceMoments::IrradianceMoments(std::uint32_t samples, std::uint32_t terms, FresnelBasis basis)
    : samples(samples), terms(terms), basis(basis), values(std::size_t(samples) * terms * 3, 0.0f) {}

std::vector<float> IrradianceMoments::combine(std::span<const double> c) const {
    std::vector<float> rgb;
    combine(c, rgb);
    return rgb;
}

void IrradianceMoments::combine(std::span<const double> c, std::vector<float>& rgb) const {
    if (c.size() != terms)
        throw Error("irradiance: " + std::to_string(c.size()) + " Fresnel coefficients for " +
                    std::to_string(terms) + " moments");
    rgb.resize(std::size_t(samples) * 3);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples, 8192), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i)
            for (int ch = 0; ch < 3; ++ch) {
                float sum = 0.0f;
                for (std::uint32_t m = 0; m < terms; ++m) sum += float(c[m]) * sample(i)[3 * m + ch];
                rgb[3 * i + ch] = sum;
            }
    });
}

IrradianceMoments& IrradianceMoments::operator+=(const IrradianceMoments& other) {
    if (other.basis != basis) throw Error("irradiance: cannot add moments taken against another Fresnel basis");
    if (other.samples != samples || other.terms != terms)
        throw Error("irradiance: cannot add " + std::to_string(other.samples) + " x " + std::to_string(other.terms) +
                    " moments to " + std::to_string(samples) + " x " + std::to_string(terms));
    for (std::size_t j = 0; j < values.size(); ++j) values[j] += other.values[j];
    return *this;
}

Imath::M33d rotationOf(const Imath::M44d& m, const char* context) {
    constexpr double kTolerance = 1e-4;
    const auto fail = [&](const std::string& what) {
        throw Error(std::string(context) + ": the transform " + what +
                    "; only rotation, translation and uniform scale are supported");
    };
    if (std::abs(m[0][3]) > kTolerance || std::abs(m[1][3]) > kTolerance || std::abs(m[2][3]) > kTolerance ||
        std::abs(m[3][3] - 1.0) > kTolerance)
        fail("is projective");
    Imath::V3d rows[3];
    for (int r = 0; r < 3; ++r) rows[r] = {m[r][0], m[r][1], m[r][2]};
    const double scale = rows[0].length();
    if (!(scale > 0.0) || !std::isfinite(scale)) fail("is singular");
    for (int r = 0; r < 3; ++r) {
        if (std::abs(rows[r].length() / scale - 1.0) > kTolerance) fail("scales non-uniformly");
        rows[r] /= scale;
    }
    if (std::abs(rows[0].dot(rows[1])) > kTolerance || std::abs(rows[0].dot(rows[2])) > kTolerance ||
        std::abs(rows[1].dot(rows[2])) > kTolerance)
        fail("shears");
    return Imath::M33d(rows[0].x, rows[0].y, rows[0].z, rows[1].x, rows[1].y, rows[1].z, rows[2].x, rows[2].y,
                       rows[2].z);
}

PlacedSamples placeSamples(std::span<const SurfaceSample> samples, const Imath::M44d& objectToWorld) {
    // Normals go through the inverse transpose, which for rotation x uniform scale is the
    // rotation itself.
    const Imath::M33d rotation = rotationOf(objectToWorld, "placing samples");
    PlacedSamples placed;
    placed.positions.reserve(samples.size());
    placed.normals.reserve(samples.size());
    for (const SurfaceSample& s : samples) {
        Imath::V3d p;
        objectToWorld.multVecMatrix(Imath::V3d(s.position), p);
        placed.positions.emplace_back(p);
        placed.normals.emplace_back((Imath::V3d(s.normal) * rotation).normalized());
    }
    return placed;
}

}  // namespace opal
