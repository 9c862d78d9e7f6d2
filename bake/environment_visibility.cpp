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
#include <string>
#include <vector>

namespace opal {

namespace {

struct CubeDirections {
    std::vector<Imath::V3f> direction;
    std::vector<float> solidAngle;
};

CubeDirections cubeDirections(const CubeMapLayout& cube) {
    CubeDirections d;
    for (std::uint32_t t = 0; t < cube.texels(); ++t) {
        d.direction.push_back(cube.direction(t));
        d.solidAngle.push_back(float(cube.solidAngle(t)));
    }
    return d;
}

// The transport vectors of one sample, m after m: vectors[m * texels + t].
void transportVectors(const SurfaceSample& s, const RayScene& scene, const CubeDirections& cube,
                      std::uint32_t terms, FresnelBasis basis, float offset, std::vector<float>& vectors) {
    const std::size_t texels = cube.direction.size();
    std::fill(vectors.begin(), vectors.end(), 0.0f);
    const Imath::V3f origin = s.position + s.normal * offset;
    for (std::size_t t = 0; t < texels; ++t) {
        const float mu = s.normal.dot(cube.direction[t]);
        if (mu <= 0.0f) continue;
        if (scene.occluded(Ray(origin, cube.direction[t], 0.0f, std::numeric_limits<float>::infinity()))) continue;
        for (std::uint32_t m = 0; m < terms; ++m)
            vectors[m * texels + t] = mu * float(fresnelBasisFunction(basis, int(m), mu)) * cube.solidAngle[t];
    }
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
    // Per sample, the kept positions (fewer than `kept` when the vector has fewer nonzero
    // coefficients: a sample facing a wall) and their values for every m.
    std::vector<SparseVector> top(samples.size());
    std::vector<std::vector<float>> values(samples.size());
    StageScope stage(progress, "environment visibility", samples.size());
    tbb::enumerable_thread_specific<std::vector<float>> scratch([&] { return std::vector<float>(M * texels); });
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples.size(), 16), [&](const auto& range) {
        cancel.throwIfRequested();
        std::vector<float>& vectors = scratch.local();
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
            transportVectors(samples[i], scene, directions, M, settings.fresnelBasis, offset, vectors);
            for (std::uint32_t m = 0; m < M; ++m)
                haarForwardCharts(std::span<float>(vectors.data() + m * texels, texels), faces);
            top[i] = keepLargest(std::span<const float>(vectors.data(), texels), kept);
            for (std::uint32_t m = 0; m < M; ++m)
                for (std::uint32_t index : top[i].indices) values[i].push_back(vectors[m * texels + index]);
        }
        stage.advance(range.size());
    });

    // CSR over (sample * M + m); every m of a sample shares the sample's positions.
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
