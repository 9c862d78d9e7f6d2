// Small translucent assets built in the test, without the bake library: samples placed in
// grid order directly (a flat slab, a cube-sphere), a profile basis fitted with small
// counts, and the compressed transfer computed by brute force from the dense T_k.
#pragma once

#include "delegate/relight/environment_light.h"
#include "delegate/relight/irradiance.h"
#include "schema/asset/cube_map.h"
#include "schema/asset/translucent_asset.h"
#include "schema/scatter/fresnel_moments.h"
#include "schema/wavelet/cdf97.h"
#include "schema/wavelet/haar.h"
#include "schema/wavelet/sparse.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

namespace opal::test {

// chartsX x chartsZ charts of 2^log2Size squared samples on the plane y = 0, normal +Y,
// `spacing` apart (scene units); chart (cx, cz) covers its own square of the slab.
inline void makeSlab(TranslucentAsset& asset, std::uint32_t chartsX, std::uint32_t chartsZ, std::uint32_t log2Size,
                     float spacing) {
    asset.layout = ChartLayout{chartsX * chartsZ, log2Size};
    const std::uint32_t size = asset.layout.size();
    asset.samples.clear();
    for (std::uint32_t cz = 0; cz < chartsZ; ++cz)
        for (std::uint32_t cx = 0; cx < chartsX; ++cx)
            for (std::uint32_t v = 0; v < size; ++v)
                for (std::uint32_t u = 0; u < size; ++u) {
                    SurfaceSample s;
                    s.position = {(float(cx * size + u) + 0.5f) * spacing, 0.0f, (float(cz * size + v) + 0.5f) * spacing};
                    s.normal = {0.0f, 1.0f, 0.0f};
                    s.area = spacing * spacing;
                    asset.samples.push_back(s);
                }
}

// A sphere of `radius` about the origin sampled at the texel centres of a cube map: 6
// charts of 2^log2Size squared samples, areas = texel solid angle x radius^2. The render
// mesh is the cube-map grid projected on the sphere (quads, one grid per face).
inline void makeCubeSphere(TranslucentAsset& asset, std::uint32_t log2Size, float radius) {
    const CubeMapLayout cube(1u << log2Size);
    asset.layout = cube.charts();
    asset.samples.clear();
    for (std::uint32_t t = 0; t < cube.texels(); ++t) {
        const Imath::V3f d = cube.direction(t);
        asset.samples.push_back({d * radius, d, float(cube.solidAngle(t)) * radius * radius});
    }
    const std::uint32_t size = cube.faceSize(), corners = size + 1;
    RenderMesh& mesh = asset.mesh;
    mesh = {};
    for (std::uint32_t face = 0; face < 6; ++face) {
        const auto base = std::int32_t(mesh.points.size());
        for (std::uint32_t v = 0; v < corners; ++v)
            for (std::uint32_t u = 0; u < corners; ++u) {
                const Imath::V3f d =
                    CubeMapLayout::faceDirection(face, 2.0f * float(u) / float(size) - 1.0f, 2.0f * float(v) / float(size) - 1.0f);
                mesh.points.push_back(d * radius);
                mesh.normals.push_back(d);
            }
        for (std::uint32_t v = 0; v < size; ++v)
            for (std::uint32_t u = 0; u < size; ++u) {
                const std::int32_t c = base + std::int32_t(v * corners + u);
                mesh.faceVertexCounts.push_back(4);
                // Counter-clockwise seen from outside: the face grids are left-handed (OpenGL
                // cube maps), so go u, then v, in reverse.
                for (std::int32_t corner : {c, c + std::int32_t(corners), c + std::int32_t(corners) + 1, c + 1})
                    mesh.faceVertexIndices.push_back(corner);
            }
    }
}

// A basis fitted with small counts over a narrow range around `material`.
inline ProfileBasis fitBasis(const EditableRange& range, int K, double rMax) {
    ProfileBasisSettings settings;
    settings.K = K;
    settings.rMax = rMax;
    settings.radialSamples = 192;
    settings.trainingMaterials = 256;
    settings.range = range;
    return ProfileBasis::fit(settings);
}

// The dense T_k[o][i] = b_k(|x_o - x_i|) A_i (mm, mm^2) of docs/ARCHITECTURE.md#transfer, one k;
// the diagonal integrates b_k over the sample's own disk of area A_o (sidecars before 2.3),
// or is 0 when the self term is left to run time (as bakes do now).
inline std::vector<double> denseTransfer(const TranslucentAsset& asset, int k,
                                         SelfTerm selfTerm = SelfTerm::InTransfer) {
    const std::size_t n = asset.samples.size();
    const double toMm = 1.0 / asset.unitsPerMm;
    std::vector<double> t(n * n);
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t o) {
        for (std::size_t i = 0; i < n; ++i) {
            const double r = (asset.samples[o].position - asset.samples[i].position).length() * toMm;
            t[o * n + i] = asset.basis.evaluate(k, r) * asset.samples[i].area * toMm * toMm;
        }
        std::vector<double> self(std::size_t(asset.basis.K()));
        asset.basis.diskIntegrals(std::sqrt(asset.samples[o].area / std::numbers::pi) * toMm, self);
        t[o * n + o] = selfTerm == SelfTerm::InTransfer ? self[std::size_t(k)] : 0.0;
    });
    return t;
}

// ^{w1}T_k^{w0^-1} by brute force: each row Haar transformed per chart (w0) keeping the
// largest keepFraction of its coefficients, then each column CDF 9/7 transformed per chart
// (w1), then the coefficients carrying energyFraction of the 9/7 energy. keep = energy = 1
// is lossless (up to float rounding).
inline SparseMatrix compressTransfer(const std::vector<double>& dense, const ChartLayout& layout, double keepFraction,
                                     double energyFraction) {
    const std::size_t n = layout.cells();
    std::vector<float> m(n * n, 0.0f);
    const auto keepCount = std::size_t(std::ceil(keepFraction * double(n)));
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t o) {
        std::vector<float> row(dense.begin() + std::ptrdiff_t(o * n), dense.begin() + std::ptrdiff_t((o + 1) * n));
        haarForwardCharts(std::span<float>(row), layout);
        const SparseVector kept = keepLargest(row, keepCount);
        for (std::size_t e = 0; e < kept.size(); ++e) m[o * n + kept.indices[e]] = kept.values[e];
    });
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t j) {
        std::vector<float> column(n);
        for (std::size_t o = 0; o < n; ++o) column[o] = m[o * n + j];
        cdf97ForwardCharts(std::span<float>(column), layout);
        for (std::size_t o = 0; o < n; ++o) m[o * n + j] = column[o];
    });
    const std::vector<float> rowNorms = cdf97SynthesisNormsSquared(layout);
    std::vector<float> norms(n * n);
    for (std::size_t p = 0; p < n; ++p) std::fill_n(norms.begin() + std::ptrdiff_t(p * n), n, rowNorms[p]);
    const SparseVector kept = keepEnergyFraction(m, energyFraction, norms);
    SparseMatrix result;
    result.cols = std::uint32_t(n);
    std::size_t e = 0;
    for (std::size_t p = 0; p < n; ++p) {
        SparseVector r;
        for (; e < kept.size() && kept.indices[e] < (p + 1) * n; ++e) {
            r.indices.push_back(std::uint32_t(kept.indices[e] - p * n));
            r.values.push_back(kept.values[e]);
        }
        appendRow(result, r);
    }
    return result;
}

inline void buildTransfer(TranslucentAsset& asset, double keepFraction, double energyFraction,
                          SelfTerm selfTerm = SelfTerm::InTransfer) {
    asset.transfer.perBasis.clear();
    asset.transfer.selfTerm = selfTerm;
    for (int k = 0; k < asset.basis.K(); ++k)
        asset.transfer.perBasis.push_back(
            compressTransfer(denseTransfer(asset, k, selfTerm), asset.layout, keepFraction, energyFraction));
}

// Environment transport vectors T_m(w) = V(x, w) mu P_m(mu) dOmega (Haar per face), as the
// bake stores them: the `keep` largest coefficients of m = 0 (all when 0) at the same
// positions for every m. visible(i, w) says whether sample i sees direction w.
inline EnvironmentTransfer environmentTransfer(const TranslucentAsset& asset, std::uint32_t faceSize,
                                               std::uint32_t terms,
                                               const std::function<bool(std::size_t, const Imath::V3f&)>& visible,
                                               std::size_t keep = 0,
                                               FresnelBasis basis = FresnelBasis::Legendre) {
    const CubeMapLayout cube(faceSize);
    std::vector<Imath::V3f> directions(cube.texels());
    std::vector<float> solidAngles(cube.texels());
    for (std::uint32_t t = 0; t < cube.texels(); ++t) {
        directions[t] = cube.direction(t);
        solidAngles[t] = float(cube.solidAngle(t));
    }
    EnvironmentTransfer env;
    env.cubeFaceSize = faceSize;
    env.fresnelTerms = terms;
    env.fresnelBasis = basis;
    env.offsets.push_back(0);
    std::vector<float> vectors(std::size_t(terms) * cube.texels());
    for (std::size_t i = 0; i < asset.samples.size(); ++i) {
        for (std::uint32_t m = 0; m < terms; ++m) {
            const std::span<float> vector(vectors.data() + std::size_t(m) * cube.texels(), cube.texels());
            for (std::uint32_t t = 0; t < cube.texels(); ++t) {
                const float mu = asset.samples[i].normal.dot(directions[t]);
                vector[t] = mu > 0.0f && visible(i, directions[t])
                                ? float(mu * fresnelBasisFunction(basis, int(m), mu)) * solidAngles[t]
                                : 0.0f;
            }
            haarForwardCharts(vector, cube.charts());
        }
        const SparseVector top =
            keepLargest(std::span<const float>(vectors.data(), cube.texels()), keep == 0 ? cube.texels() : keep);
        for (std::uint32_t m = 0; m < terms; ++m) {
            for (std::uint32_t t : top.indices) {
                env.indices.push_back(t);
                env.values.push_back(vectors[std::size_t(m) * cube.texels() + t]);
            }
            env.offsets.push_back(std::uint32_t(env.indices.size()));
        }
    }
    return env;
}

// A width x height lat-long map whose pixel centres take f(direction).
inline std::shared_ptr<LatLongMap> latLongMap(int width, int height,
                                              const std::function<Imath::V3f(const Imath::V3d&)>& f) {
    std::vector<float> rgb;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Imath::V3f v = f(LatLongMap::direction((x + 0.5) / width, (y + 0.5) / height));
            rgb.insert(rgb.end(), {v.x, v.y, v.z});
        }
    return std::make_shared<LatLongMap>(width, height, std::move(rgb));
}

// Random positive moments (E_0 dominant, as real irradiance).
inline IrradianceMoments randomMoments(std::uint32_t samples, std::uint32_t terms, std::uint32_t seed) {
    IrradianceMoments e(samples, terms);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (std::uint32_t i = 0; i < samples; ++i)
        for (std::uint32_t m = 0; m < terms; ++m)
            for (int c = 0; c < 3; ++c) e.sample(i)[3 * m + c] = m == 0 ? 1.0f + uniform(rng) : 0.3f * uniform(rng);
    return e;
}

inline EditableRange rangeAround(const Material& m, double factor, double etaMin, double etaMax) {
    EditableRange range;
    range.sigmaSPrimeMin = std::min({m.sigmaSPrime[0], m.sigmaSPrime[1], m.sigmaSPrime[2]}) / factor;
    range.sigmaSPrimeMax = std::max({m.sigmaSPrime[0], m.sigmaSPrime[1], m.sigmaSPrime[2]}) * factor;
    range.sigmaAMin = std::min({m.sigmaA[0], m.sigmaA[1], m.sigmaA[2]}) / factor;
    range.sigmaAMax = std::max({m.sigmaA[0], m.sigmaA[1], m.sigmaA[2]}) * factor;
    range.etaMin = etaMin;
    range.etaMax = etaMax;
    return range;
}

// max |a - b| / max |b|.
inline double maxRelative(std::span<const float> a, std::span<const float> b) {
    double diff = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) {
        diff = std::max(diff, std::abs(double(a[i]) - double(b[i])));
        scale = std::max(scale, std::abs(double(b[i])));
    }
    return diff / scale;
}

// sqrt(sum (a - b)^2 / sum b^2).
inline double relativeRmse(std::span<const float> a, std::span<const float> b) {
    double diff = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) {
        diff += (double(a[i]) - double(b[i])) * (double(a[i]) - double(b[i]));
        norm += double(b[i]) * double(b[i]);
    }
    return std::sqrt(diff / norm);
}

}  // namespace opal::test
