#include "bench/relight_reference.h"

#include "bench/cpu_time.h"
#include "bench/random_outputs.h"
#include "bench/relight_scene.h"
#include "delegate/relight/reference_gather.h"
#include "delegate/relight/stopwatch.h"
#include "delegate/relight/relight_engine.h"
#include "delegate/relight/vertex_gather.h"

#include <algorithm>
#include <cmath>

namespace opal::bench {

RelightReference::RelightReference(const RelightScene& scene, std::shared_ptr<const TranslucentAsset> asset,
                                   std::shared_ptr<const LatLongMap> domeMap, const Material& material,
                                   std::size_t outputs, std::vector<double> peerMaxErrors)
    : asset_(asset),
      domeMap_(std::move(domeMap)),
      irradiance_(asset, Imath::M44d()),
      material_(material),
      outputs_(randomOutputs(asset->samples.size(), outputs)),
      peerMaxErrors_(std::move(peerMaxErrors)) {
    if (!peerMaxErrors_.empty()) {
        const Stopwatch clock;
        octree_.emplace(*asset_);
        octreeMs_ = clock.ms();
        engine_.emplace(asset_);
    }
    rays_.addMesh(asset_->mesh, Imath::M44d());
    rays_.commit();
    if (scene.hasKeyLight())
        irradiance_.setLight(RelightScene::KeyLightPath, AnalyticLight::fromDesc(scene.keyLight()), rays_);
    if (scene.hasDome())
        irradiance_.setLight(RelightScene::DomePath,
                             std::make_shared<const EnvironmentLight>(EnvironmentLight::fromDesc(domeMap_, scene.dome())));
}

ReferenceTiming RelightReference::materialEdit(const Material& material) {
    material_ = material;
    ReferenceTiming timing;
    radiance(timing, true);
    return timing;
}

ReferenceTiming RelightReference::keyLightMove(const hd::LightDesc& key) {
    ReferenceTiming timing;
    const Stopwatch clock;
    irradiance_.setLight(RelightScene::KeyLightPath, AnalyticLight::fromDesc(key), rays_);
    timing.irradianceMs = clock.ms();
    radiance(timing, true);
    return timing;
}

ReferenceTiming RelightReference::domeRotation(const hd::LightDesc& dome) {
    ReferenceTiming timing;
    const Stopwatch clock;
    irradiance_.setLight(RelightScene::DomePath,
                         std::make_shared<const EnvironmentLight>(EnvironmentLight::fromDesc(domeMap_, dome)));
    timing.irradianceMs = clock.ms();
    radiance(timing, false);
    return timing;
}

void RelightReference::radiance(ReferenceTiming& timing, bool withPeer) {
    const std::size_t samples = asset_->samples.size();
    const Stopwatch exactClock;
    const std::vector<float> exact = irradiance_.exactIrradiance(material_.eta);
    timing.exactMs = exactClock.ms();

    const double cpu = processCpuMilliseconds();
    const Stopwatch gatherClock;
    const std::vector<float> gathered = referenceGather(*asset_, material_, exact, outputs_);
    timing.measuredGatherMs = gatherClock.ms();
    // Exactly linear in the outputs: every output is the same loop over all N samples.
    const double scale = double(samples) / double(outputs());
    timing.gatherMs = timing.measuredGatherMs * scale;
    timing.gatherCpuMs = (processCpuMilliseconds() - cpu) * scale;

    // The vertices in full (a partial gather leaves the other samples at zero: the cost
    // does not depend on the values).
    std::vector<float> perSample;
    if (extrapolated()) {
        perSample.assign(3 * samples, 0.0f);
        for (std::size_t j = 0; j < outputs_.size(); ++j)
            std::copy_n(gathered.begin() + 3 * j, 3, perSample.begin() + 3 * std::size_t(outputs_[j]));
    }
    const VertexGather gather(asset_->vertexWeights, samples);  // as an engine holds it: not timed
    std::vector<float> vertexRadiance(3 * gather.vertices()), vertexIrradiance(3 * gather.vertices());
    std::vector<Float4> scratch;
    const Stopwatch verticesClock;
    gather.apply(extrapolated() ? perSample : gathered, vertexRadiance, scratch);
    gather.apply(exact, vertexIrradiance, scratch);
    timing.verticesMs = verticesClock.ms();
    if (octree_ && withPeer) timing.peer = peer(exact, gathered);
}

PeerTiming RelightReference::peer(std::span<const float> exact, std::span<const float> gathered) {
    PeerTiming timing;
    timing.structureMs = octreeMs_;
    const Stopwatch refitClock;
    octree_->setIrradiance(exact);
    timing.refitMs = refitClock.ms();
    for (double maxError : peerMaxErrors_) {
        const Stopwatch clock;
        const JensenBuhlerOctree::Result result = octree_->radiance(material_, maxError);
        timing.sweep.push_back({maxError, clock.ms(), result.interactionsPerOutput, relativeRmse(result.radiance, gathered)});
    }
    engine_->setIrradiance(irradiance_.moments());
    engine_->setMaterial(material_);
    timing.engineRelativeRmse = relativeRmse(engine_->sampleRadiance(), gathered);
    return timing;
}

// sqrt(sum |a - b|^2 / sum |b|^2) over the gather's outputs; all: every sample x 3.
double RelightReference::relativeRmse(std::span<const float> all, std::span<const float> gathered) const {
    double diff = 0.0, norm = 0.0;
    for (std::size_t j = 0; j < outputs(); ++j) {
        const std::size_t sample = extrapolated() ? outputs_[j] : j;
        for (int c = 0; c < 3; ++c) {
            const double a = all[3 * sample + c], b = gathered[3 * j + c];
            diff += (a - b) * (a - b);
            norm += b * b;
        }
    }
    return std::sqrt(diff / norm);
}

}  // namespace opal::bench
