#include "delegate/relight/environment_reference.h"

#include "schema/error.h"
#include "schema/scatter/dipole.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <string>

namespace opal {

namespace {

// As the bake's environment visibility: rays start this fraction of the mesh's extent
// along the normal, clear of the surface the sample lies on.
constexpr float kRayOffset = 1e-4f;

const TranslucentAsset& require(const std::shared_ptr<const TranslucentAsset>& asset) {
    if (!asset) throw Error("dome reference: no asset");
    return *asset;
}

}  // namespace

// The rays of one sample, the texels they go to, Embree's answers, and the sample's
// visibility bits when they are not kept.
struct EnvironmentReference::TraceScratch {
    std::vector<Ray> rays;
    std::vector<std::uint32_t> texels;
    std::vector<std::uint8_t> blocked;
    std::vector<std::uint64_t> bits;
};

std::uint32_t EnvironmentReference::faceSizeFor(const TranslucentAsset& asset) {
    return std::min(std::max(kMinFaceSize, 2 * asset.environment.cubeFaceSize), CubeMapLayout::kMaxFaceSize);
}

EnvironmentReference::EnvironmentReference(std::shared_ptr<const TranslucentAsset> asset, std::uint32_t faceSize,
                                           std::size_t visibilityBudget)
    : asset_(std::move(asset)), cube_(faceSize), scene_(RayScene::BuildQuality::High) {
    const TranslucentAsset& a = require(asset_);
    directions_.resize(cube_.texels());
    solidAngles_.resize(cube_.texels());
    for (std::uint32_t t = 0; t < cube_.texels(); ++t) {
        directions_[t] = cube_.direction(t);
        solidAngles_[t] = cube_.solidAngle(t);
    }
    if (!a.mesh.faceVertexCounts.empty()) scene_.addMesh(a.mesh, Imath::M44d());
    scene_.commit();
    offset_ = kRayOffset * scene_.extent();

    const std::size_t samples = a.samples.size();
    if (samples * wordsPerSample() * sizeof(std::uint64_t) > visibilityBudget) return;
    visibility_.resize(samples * wordsPerSample());
    tbb::enumerable_thread_specific<TraceScratch> scratch;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples, 4), [&](const auto& range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i)
            traceVisibility(i, std::span<std::uint64_t>(visibility_.data() + i * wordsPerSample(), wordsPerSample()),
                            scratch.local());
    });
}

void EnvironmentReference::traceVisibility(std::size_t i, std::span<std::uint64_t> bits, TraceScratch& s) const {
    const SurfaceSample& sample = asset_->samples[i];
    const Imath::V3f origin = sample.position + sample.normal * offset_;
    s.rays.clear();
    s.texels.clear();
    for (std::uint32_t t = 0; t < cube_.texels(); ++t) {
        if (sample.normal.dot(directions_[t]) <= 0.0f) continue;  // the bake's horizon test
        s.rays.emplace_back(origin, directions_[t], 0.0f, std::numeric_limits<float>::infinity());
        s.texels.push_back(t);
    }
    s.blocked.resize(s.rays.size());
    // Neighbouring texels from one origin: coherent packets.
    scene_.occludedCoherent(s.rays, s.blocked);
    std::fill(bits.begin(), bits.end(), 0);
    for (std::size_t k = 0; k < s.texels.size(); ++k)
        if (!s.blocked[k]) bits[s.texels[k] / 64] |= std::uint64_t(1) << (s.texels[k] % 64);
}

std::vector<float> EnvironmentReference::irradiance(const EnvironmentLight& dome, const Imath::M44d& objectToWorld,
                                                    double eta) const {
    if (!(eta > 0.0) || !std::isfinite(eta))
        throw Error("dome reference: eta must be positive and finite, got " + std::to_string(eta));
    const std::vector<float> radiance = dome.cubeRadiance(cube_, objectToWorld);  // texels x 3, object space
    const std::size_t samples = asset_->samples.size();
    std::vector<float> e(samples * 3);
    tbb::enumerable_thread_specific<TraceScratch> scratch;  // beyond the budget only
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples, 16), [&](const auto& range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
            std::span<const std::uint64_t> bits;
            if (visibilityCached()) {
                bits = std::span<const std::uint64_t>(visibility_.data() + i * wordsPerSample(), wordsPerSample());
            } else {
                TraceScratch& own = scratch.local();
                own.bits.resize(wordsPerSample());
                traceVisibility(i, own.bits, own);
                bits = own.bits;
            }
            sampleIrradiance(asset_->samples[i].normal, bits, radiance, eta, std::span<float, 3>(e.data() + i * 3, 3));
        }
    });
    return e;
}

// sum over the visible texels t of L_t F_t(eta, mu_t) mu_t dOmega_t, in double.
void EnvironmentReference::sampleIrradiance(const Imath::V3f& normal, std::span<const std::uint64_t> bits,
                                            std::span<const float> radiance, double eta, std::span<float, 3> e) const {
    double total[3] = {0.0, 0.0, 0.0};
    for (std::size_t w = 0; w < bits.size(); ++w)
        for (std::uint64_t word = bits[w]; word != 0; word &= word - 1) {
            const std::size_t t = w * 64 + std::size_t(std::countr_zero(word));
            const double mu = double(normal.dot(directions_[t]));  // > 0: the bit says so
            const double weight = fresnelTransmittance(eta, mu) * mu * solidAngles_[t];
            for (int c = 0; c < 3; ++c) total[c] += weight * double(radiance[t * 3 + c]);
        }
    for (int c = 0; c < 3; ++c) e[std::size_t(c)] = float(total[c]);
}

std::size_t EnvironmentReference::memoryBytes() const {
    return visibility_.capacity() * sizeof(std::uint64_t) + directions_.capacity() * sizeof(Imath::V3f) +
           solidAngles_.capacity() * sizeof(double);
}

}  // namespace opal
