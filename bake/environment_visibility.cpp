#include "bake/environment_visibility.h"

#include "raytrace/ray_scene.h"
#include "schema/asset/cube_map.h"
#include "schema/scatter/fresnel_moments.h"
#include "schema/wavelet/haar.h"
#include "schema/wavelet/sparse.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace opal {

namespace {

constexpr double kPi = std::numbers::pi;

constexpr int kRaysPerAxis = 2;  // per texel: 2 x 2 rays
constexpr int kRaysPerTexel = kRaysPerAxis * kRaysPerAxis;

// Per texel: its centre, and its rays' directions with their shares of its solid angle
// (rays[t * kRaysPerTexel + r]).
struct CubeDirections {
    std::uint32_t faceSize = 0;
    std::vector<Imath::V3f> centre;
    std::vector<Imath::V3f> ray;
    std::vector<float> share;
};

CubeDirections cubeDirections(const CubeMapLayout& cube) {
    CubeDirections d;
    const std::uint32_t size = d.faceSize = cube.faceSize();
    for (std::uint32_t t = 0; t < cube.texels(); ++t) {
        d.centre.push_back(cube.direction(t));
        const CubeMapTexel texel = cube.texel(t);
        double weights[kRaysPerTexel], total = 0.0;
        for (int r = 0; r < kRaysPerTexel; ++r) {
            const double u = 2.0 * (texel.u + (r % kRaysPerAxis + 0.5) / kRaysPerAxis) / size - 1.0;
            const double v = 2.0 * (texel.v + (r / kRaysPerAxis + 0.5) / kRaysPerAxis) / size - 1.0;
            const double q = 1.0 + u * u + v * v;
            total += weights[r] = 1.0 / (q * std::sqrt(q));  // solid angle per unit face area
            d.ray.push_back(CubeMapLayout::faceDirection(texel.face, float(u), float(v)));
        }
        for (int r = 0; r < kRaysPerTexel; ++r) d.share.push_back(float(weights[r] / total * cube.solidAngle(t)));
    }
    return d;
}

// One sample's rays above its horizon, the ray index of each, and Embree's answers.
struct RayScratch {
    std::vector<Ray> rays;
    std::vector<std::uint32_t> index;
    std::vector<std::uint8_t> blocked;
    std::vector<float> vectors;  // M x texels
};

// The occluded residual vectors of one sample, m after m: vectors[m * texels + t] = the sum,
// over the texel's rays above the sample's horizon that hit the mesh, of mu P_m(mu) times
// the ray's share of the texel's solid angle.
// Returns whether any ray was blocked (else every vector is zero).
bool occludedVectors(const SurfaceSample& s, const RayScene& scene, const CubeDirections& cube, std::uint32_t terms,
                     FresnelBasis basis, float offset, RayScratch& scratch) {
    const std::size_t texels = cube.centre.size();
    const float horizon = -2.0f / float(cube.faceSize);
    std::fill(scratch.vectors.begin(), scratch.vectors.end(), 0.0f);
    scratch.rays.clear();
    scratch.index.clear();
    const Imath::V3f origin = s.position + s.normal * offset;
    for (std::uint32_t t = 0; t < texels; ++t) {
        // A texel whose centre lies more than 2 / size below the horizon (more than the
        // texel's angular half-diagonal) lies wholly below it.
        if (s.normal.dot(cube.centre[t]) < horizon) continue;
        for (std::uint32_t r = t * kRaysPerTexel; r < (t + 1) * kRaysPerTexel; ++r)
            if (s.normal.dot(cube.ray[r]) > 0.0f) {
                scratch.rays.emplace_back(origin, cube.ray[r], 0.0f, std::numeric_limits<float>::infinity());
                scratch.index.push_back(r);
            }
    }
    scratch.blocked.resize(scratch.rays.size());
    scene.occludedCoherent(scratch.rays, scratch.blocked);  // neighbouring rays from one origin
    bool any = false;
    for (std::size_t k = 0; k < scratch.rays.size(); ++k) {
        if (!scratch.blocked[k]) continue;
        any = true;
        const std::uint32_t r = scratch.index[k], t = r / kRaysPerTexel;
        const float mu = s.normal.dot(cube.ray[r]);
        for (std::uint32_t m = 0; m < terms; ++m)
            scratch.vectors[m * texels + t] += float(mu * fresnelBasisFunction(basis, int(m), mu)) * cube.share[r];
    }
    return any;
}

// The kept positions of one sample's m = 0 vector: the fewest largest whose dropped energy is
// at most `budget`, at most `cap` of them.
SparseVector keepPositions(std::span<const float> coefficients, double budget, std::uint32_t cap) {
    double total = 0.0;
    for (float c : coefficients) total += double(c) * c;
    if (total <= budget) return {};
    SparseVector kept = keepEnergyFraction(coefficients, 1.0 - budget / total);
    return kept.size() > cap ? keepLargest(coefficients, cap) : kept;
}

}  // namespace

EnvironmentTransfer buildEnvironmentTransfer(const RenderMesh& mesh, std::span<const SurfaceSample> samples,
                                             const VisibilitySettings& settings, ProgressSink* progress,
                                             const CancelToken& cancel) {
    if (settings.fresnelTerms < 1 || settings.fresnelTerms > std::uint32_t(kMaxFresnelTerms))
        throw Error("environment visibility: 1 to " + std::to_string(kMaxFresnelTerms) + " Fresnel terms, got " +
                    std::to_string(settings.fresnelTerms));
    const CubeMapLayout cube(settings.cubeFaceSize);
    const ChartLayout faces = cube.charts();
    const std::size_t texels = cube.texels();
    const std::uint32_t kept = std::min<std::uint32_t>(settings.terms, std::uint32_t(texels));
    if (kept == 0) throw Error("environment visibility: --env-terms must be at least 1");
    if (!(settings.error >= 0.0 && settings.error <= 1.0))
        throw Error("environment visibility: --env-error must be in [0, 1], got " + std::to_string(settings.error));
    // The energy of an open hemisphere's m = 0 vector: integral of mu^2 dOmega = 2 pi / 3,
    // times one texel's mean solid angle.
    const double budget = settings.error * settings.error * (2.0 * kPi / 3.0) * (4.0 * kPi / double(texels));
    const CubeDirections directions = cubeDirections(cube);
    RayScene scene(RayScene::BuildQuality::High);
    scene.addMesh(mesh, Imath::M44d());
    scene.commit();
    const float offset = 1e-4f * scene.extent();

    const std::uint32_t M = settings.fresnelTerms;
    EnvironmentTransfer out;
    out.cubeFaceSize = settings.cubeFaceSize;
    out.fresnelTerms = M;
    out.fresnelBasis = settings.fresnelBasis;
    out.kind = EnvironmentVectorKind::Occluded;
    // Per sample, the kept positions (none for a sample that sees its whole hemisphere) and
    // their values for every m.
    std::vector<SparseVector> top(samples.size());
    std::vector<std::vector<float>> values(samples.size());
    StageScope stage(progress, "environment visibility", samples.size());
    tbb::enumerable_thread_specific<RayScratch> scratch([&] { return RayScratch{{}, {}, {}, std::vector<float>(M * texels)}; });
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples.size(), 16), [&](const auto& range) {
        cancel.throwIfRequested();
        RayScratch& own = scratch.local();
        std::vector<float>& vectors = own.vectors;
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
            if (!occludedVectors(samples[i], scene, directions, M, settings.fresnelBasis, offset, own))
                continue;  // an open sample: no terms
            for (std::uint32_t m = 0; m < M; ++m)
                haarForwardCharts(std::span<float>(vectors.data() + m * texels, texels), faces);
            top[i] = keepPositions(std::span<const float>(vectors.data(), texels), budget, kept);
            for (std::uint32_t m = 0; m < M; ++m)
                for (std::uint32_t index : top[i].indices) values[i].push_back(vectors[m * texels + index]);
        }
        stage.advance(range.size());
    });

    // CSR over (sample * M + m); every m of a sample shares the sample's positions.
    std::uint64_t entries = 0;
    for (const SparseVector& kept : top) entries += std::uint64_t(kept.size()) * M;
    if (entries > std::numeric_limits<std::uint32_t>::max())
        throw Error("environment visibility: " + std::to_string(entries) +
                    " terms in all do not fit the sidecar's 32-bit offsets; lower --env-terms, raise --env-error or "
                    "bake fewer --samples");
    out.offsets.assign(1, 0);
    for (std::size_t i = 0; i < samples.size(); ++i)
        for (std::uint32_t m = 0; m < M; ++m) {
            const std::size_t count = top[i].size();
            out.indices.insert(out.indices.end(), top[i].indices.begin(), top[i].indices.end());
            out.values.insert(out.values.end(), values[i].begin() + m * count, values[i].begin() + (m + 1) * count);
            out.offsets.push_back(std::uint32_t(out.indices.size()));
        }
    return out;
}

}  // namespace opal
