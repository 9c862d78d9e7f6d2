#include "schema/asset/self_term.h"

#include "schema/error.h"
#include "schema/scatter/dipole.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace opal {

void selfTermReflectance(std::span<const SurfaceSample> samples, double unitsPerMm, const Material& material,
                         std::span<float> out) {
    if (out.size() != 3 * samples.size())
        throw Error("self term: " + std::to_string(out.size()) + " outputs for " + std::to_string(samples.size()) +
                    " RGB samples");
    if (!(unitsPerMm > 0.0 && std::isfinite(unitsPerMm)))
        throw Error("self term: units per mm must be positive and finite, got " + std::to_string(unitsPerMm));
    const double toMm = 1.0 / unitsPerMm;
    // Blocks in parallel (a material edit waits for this), each evaluating R_disk again
    // where the area changes from the sample before.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples.size(), 8192), [&](const tbb::blocked_range<std::size_t>& r) {
        float area = -1.0f;  // no sample has a negative area: the block's first one evaluates
        float reflectance[3] = {0.0f, 0.0f, 0.0f};
        for (std::size_t o = r.begin(); o != r.end(); ++o) {
            if (samples[o].area != area) {
                area = samples[o].area;
                const double radius = std::sqrt(double(area) / std::numbers::pi) * toMm;
                for (int c = 0; c < 3; ++c) reflectance[c] = float(dipoleDiskReflectance(radius, material.channel(c)));
            }
            for (int c = 0; c < 3; ++c) out[3 * o + std::size_t(c)] = reflectance[c];
        }
    });
}

double profileFitRadius(const TranslucentAsset& asset) {
    if (asset.transfer.selfTerm != SelfTerm::AtRunTime || asset.samples.empty()) return 0.0;
    float area = asset.samples[0].area;
    for (const SurfaceSample& s : asset.samples) area = std::min(area, s.area);
    return std::sqrt(std::max(double(area), 0.0) / std::numbers::pi) / asset.unitsPerMm;
}

}  // namespace opal
