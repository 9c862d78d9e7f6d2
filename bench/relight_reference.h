// The exact reference for the edits `opal-bench relight` times: what the delegate's
// opal:reference mode does in a commit (translucent_mesh.cpp), made with the same library
// calls on the bench's own copies of the scene's state:
//
//   light or dome edit   the changed light's E_m at every sample (MeshIrradiance::setLight:
//                        Embree shadow rays, or the dome's re-projection)
//   every edit           the exact E(x_i; eta) (F_t(eta, .) per analytic light)
//                        L(x_o) = (1/pi) sum_i R_d(|x_o - x_i|) A_i E(x_i)   for every x_o
//                        (delegate/relight/reference_gather.h: O(N) per output, O(N^2) in all)
//                        L and E interpolated to the render-mesh vertices
//
// The gather may be run on a random subset of the outputs and scaled to all of them: its
// cost is exactly linear in the outputs (each output is the same O(N) loop), while the
// other steps always run in full.
//
// With the peer on (--peer jensen-buhler), material edits and key-light moves also run Jensen and Buhler's
// hierarchical dipole (bench/jensen_buhler.h) on the same exact E and material, at each
// maxError of a sweep, and measures its error and the engine's (RelightEngine on the same
// irradiance moments and material) against the gather, at the gather's outputs.
#pragma once

#include "bench/jensen_buhler.h"
#include "delegate/relight/environment_light.h"
#include "delegate/relight/mesh_irradiance.h"
#include "delegate/relight/relight_engine.h"
#include "raytrace/ray_scene.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace opal::bench {

class RelightScene;

// The peer at one maxError: the evaluation over every sample and its error.
struct PeerPoint {
    double maxError = 0.0;
    double evaluateMs = 0.0;            // L at every sample from the octree
    double interactionsPerOutput = 0.0; // dipole evaluations per output
    double relativeRmse = 0.0;          // against the gather, at its outputs
};

struct PeerTiming {
    double structureMs = 0.0;  // the octree's cells (positions only: once per asset)
    double refitMs = 0.0;      // the node aggregates for this edit's E (per light change)
    std::vector<PeerPoint> sweep;
    double engineRelativeRmse = 0.0;  // RelightEngine on the same edit, same outputs
};

struct ReferenceTiming {
    double irradianceMs = 0.0;      // the changed light's E_m (light and dome edits)
    double exactMs = 0.0;           // the exact E for the material's eta
    double gatherMs = 0.0;          // the O(N^2) gather, for every output (scaled if partial)
    double measuredGatherMs = 0.0;  // the gather as run (equal to gatherMs when not partial)
    double gatherCpuMs = 0.0;       // the process's CPU time over the gather, scaled as gatherMs
    double verticesMs = 0.0;        // L and E to the render-mesh vertices

    std::optional<PeerTiming> peer;

    double totalMs() const { return irradianceMs + exactMs + gatherMs + verticesMs; }
};

class RelightReference {
public:
    // Takes the scene's current lights and material (untimed). outputs: how many random
    // output samples the gather evaluates (0, or at least the sample count: all of them).
    // peerMaxErrors: the peer's sweep (empty: no peer).
    RelightReference(const RelightScene& scene, std::shared_ptr<const TranslucentAsset> asset,
                     std::shared_ptr<const LatLongMap> domeMap, const Material& material, std::size_t outputs,
                     std::vector<double> peerMaxErrors = {});

    std::size_t outputs() const { return outputs_.empty() ? asset_->samples.size() : outputs_.size(); }
    bool extrapolated() const { return !outputs_.empty(); }

    ReferenceTiming materialEdit(const Material& material);
    ReferenceTiming keyLightMove(const hd::LightDesc& key);
    ReferenceTiming domeRotation(const hd::LightDesc& dome);

private:
    // Exact E, the gather, the vertices; the peer too when asked and on.
    void radiance(ReferenceTiming& timing, bool withPeer);
    PeerTiming peer(std::span<const float> exact, std::span<const float> gathered);
    double relativeRmse(std::span<const float> all, std::span<const float> gathered) const;

    std::shared_ptr<const TranslucentAsset> asset_;
    std::shared_ptr<const LatLongMap> domeMap_;
    RayScene rays_;
    MeshIrradiance irradiance_;
    Material material_;
    std::vector<std::uint32_t> outputs_;  // empty: every sample
    std::vector<double> peerMaxErrors_;
    std::optional<JensenBuhlerOctree> octree_;
    double octreeMs_ = 0.0;
    std::optional<RelightEngine> engine_;
};

}  // namespace opal::bench
