#include "schema/asset/display_color.h"

#include "schema/scatter/acescg_from_xyz.h"
#include "schema/scatter/dipole.h"

#include <Imath/ImathMatrix.h>

#include <algorithm>
#include <numbers>

namespace opal {
namespace {

// XYZ (D65) -> linear Rec.709, IEC 61966-2-1 (sRGB primaries, D65 white).
constexpr double kXyzD65ToRec709[3][3] = {{3.2404542, -1.5371385, -0.4985314},
                                          {-0.9692660, 1.8760108, 0.0415560},
                                          {0.0556434, -0.2040259, 1.0572252}};

// Irradiance under the uniform dome of radiance 1 at each sample, from its m = 0
// environment vector: the map of 1 has, per face, only the Haar DC term n (orthonormal Haar,
// schema/wavelet/haar.h), so E = n sum_faces T[face DC], or pi - n sum_faces O[face DC]
// for occluded residuals (pi: the unoccluded integral of mu).
std::vector<double> domeIrradiance(const TranslucentAsset& asset) {
    const EnvironmentTransfer& env = asset.environment;
    std::vector<double> e(asset.samples.size(), std::numbers::pi);
    if (env.offsets.empty()) return e;
    const std::uint32_t n = env.cubeFaceSize, faceTexels = n * n;
    for (std::size_t i = 0; i < e.size(); ++i) {
        const std::size_t row = i * env.fresnelTerms;  // m = 0
        double sum = 0.0;
        for (std::uint32_t k = env.offsets[row]; k < env.offsets[row + 1]; ++k)
            if (env.indices[k] % faceTexels == 0) sum += env.values[k];
        e[i] = env.kind == EnvironmentVectorKind::Occluded ? std::numbers::pi - double(n) * sum : double(n) * sum;
    }
    return e;
}

// Acts on column vectors, out_i = sum_j m[i][j] v_j, as the ColorMatrix constants do
// (Imath's own vector product is v * m, row vectors).
Imath::V3d apply(const Imath::M33d& m, const Imath::V3d& v) { return v * m.transposed(); }

Imath::M33d rec709FromAcescgMatrix() {
    Imath::M33d toAcescg, toRec709;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            toAcescg[i][j] = kXyzD65ToAcescg[i][j];
            toRec709[i][j] = kXyzD65ToRec709[i][j];
        }
    return toRec709 * toAcescg.inverse();
}

}  // namespace

Imath::V3d rec709FromAcescg(const Imath::V3d& acescg) { return apply(rec709FromAcescgMatrix(), acescg); }

std::vector<Imath::V3f> displayColors(const TranslucentAsset& asset) {
    const VertexWeights& w = asset.vertexWeights;
    if (w.offsets.size() < 2) return {};
    const Material& m = asset.defaultMaterial;
    Imath::V3d albedo;
    for (int c = 0; c < 3; ++c)
        albedo[c] = dipoleTotalReflectance(m.sigmaSPrime[c] / (m.sigmaSPrime[c] + m.sigmaA[c]), m.eta);
    const std::vector<double> e = domeIrradiance(asset);
    const Imath::M33d toRec709 = rec709FromAcescgMatrix();
    std::vector<Imath::V3f> colors(w.offsets.size() - 1);
    for (std::size_t v = 0; v + 1 < w.offsets.size(); ++v) {
        double ev = 0.0, total = 0.0;
        for (std::uint32_t k = w.offsets[v]; k < w.offsets[v + 1]; ++k) {
            ev += w.weights[k] * e[w.samples[k]];
            total += w.weights[k];
        }
        const double scale = total > 0.0 ? ev / total / std::numbers::pi : 0.0;
        const Imath::V3d rgb = apply(toRec709, albedo * scale);
        colors[v] = Imath::V3f(float(std::max(0.0, rgb.x)), float(std::max(0.0, rgb.y)), float(std::max(0.0, rgb.z)));
    }
    return colors;
}

}  // namespace opal
