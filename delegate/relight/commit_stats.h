// What a commitResources did and how long it took: for hosts (a viewer's status line),
// benchmarks (irradiance vs products vs material time) and tests (a material edit must not
// recompute irradiance products). The delegate reports them in renderStats() too
// (delegate/DELEGATE.md#render-stats).
#pragma once

#include <algorithm>
#include <cstdint>

namespace opal {

struct CommitStats {
    // Wall-clock milliseconds.
    double totalMs = 0.0;        // the whole commitResources
    double rayScenesMs = 0.0;    // rebuilding the Embree scene
    double irradianceMs = 0.0;   // E_m at the samples: lights, shadows, domes (MeshIrradiance)
    // Of irradianceMs: the moments of each light added or changed (MeshIrradiance::lastUpdate;
    // a dome's: its map on the cube and the vectors' sums).
    double lightMomentsMs = 0.0;
    double productsMs = 0.0;     // y_k = (w1 T_k w0^-1) w0 E (RelightEngine::setIrradiance)
    double materialMs = 0.0;     // s_k, the weighted sum, inverse 9/7, the vertices (setMaterial, outputs)
    double referenceMs = 0.0;    // the exact gather (opal:reference)

    // Counts of work done.
    std::uint64_t rayScenes = 0;           // Embree scenes built
    std::uint64_t lightEvaluations = 0;    // one light's E at one mesh's samples
    std::uint64_t irradianceProducts = 0;  // RelightEngine::setIrradiance calls
    std::uint64_t materialUpdates = 0;     // RelightEngine::setMaterial calls
    std::uint64_t referenceGathers = 0;    // exact O(N^2) gathers of one mesh

    // Values the engines set to zero (RelightEngine::radianceNoise, irradianceNoise), and
    // the deepest as a fraction of its mesh's highest L or E (<= 0), over the meshes relit.
    std::uint64_t projectedValues = 0, projectedIrradiance = 0;
    double deepestProjected = 0.0, deepestIrradiance = 0.0;

    CommitStats& operator+=(const CommitStats& o) {
        totalMs += o.totalMs;
        rayScenesMs += o.rayScenesMs;
        irradianceMs += o.irradianceMs;
        lightMomentsMs += o.lightMomentsMs;
        productsMs += o.productsMs;
        materialMs += o.materialMs;
        referenceMs += o.referenceMs;
        rayScenes += o.rayScenes;
        lightEvaluations += o.lightEvaluations;
        irradianceProducts += o.irradianceProducts;
        materialUpdates += o.materialUpdates;
        referenceGathers += o.referenceGathers;
        projectedValues += o.projectedValues;
        projectedIrradiance += o.projectedIrradiance;
        deepestProjected = std::min(deepestProjected, o.deepestProjected);
        deepestIrradiance = std::min(deepestIrradiance, o.deepestIrradiance);
        return *this;
    }
};

}  // namespace opal
