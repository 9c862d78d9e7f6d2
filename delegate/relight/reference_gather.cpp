#include "delegate/relight/reference_gather.h"

#include "schema/error.h"
#include "schema/scatter/dipole.h"
#include "schema/scatter/dipole_profile.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <numbers>
#include <string>

namespace opal {

std::vector<float> referenceGather(const TranslucentAsset& asset, const Material& material,
                                   std::span<const float> irradiance, std::span<const std::uint32_t> outputs) {
    const std::size_t n = asset.samples.size();
    if (irradiance.size() != 3 * n)
        throw Error("reference gather: " + std::to_string(irradiance.size()) + " irradiance values for " +
                    std::to_string(n) + " RGB samples");
    validateMaterial(material, "reference gather");
    for (std::uint32_t o : outputs)
        if (o >= n) throw Error("reference gather: output sample " + std::to_string(o) + " out of range");
    const double toMm = 1.0 / asset.unitsPerMm;
    const DipoleProfile profile[3] = {DipoleProfile(material.channel(0)), DipoleProfile(material.channel(1)),
                                     DipoleProfile(material.channel(2))};
    const std::size_t count = outputs.empty() ? n : outputs.size();
    std::vector<float> radiance(3 * count);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 16), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t j = r.begin(); j != r.end(); ++j) {
            const std::size_t o = outputs.empty() ? j : outputs[j];
            const Imath::V3d xo(asset.samples[o].position);
            double sum[3] = {0.0, 0.0, 0.0};
            for (std::size_t i = 0; i < n; ++i) {
                if (i == o) continue;
                const SurfaceSample& s = asset.samples[i];
                const double r2 = (Imath::V3d(s.position) - xo).length2() * toMm * toMm;  // mm^2
                const double area = s.area * toMm * toMm;                                   // mm^2
                for (int c = 0; c < 3; ++c) sum[c] += profile[c](r2) * area * irradiance[3 * i + c];
            }
            // The sample's own light, gathered over its own disk, as the bake does
            // (docs/ARCHITECTURE.md#total-reflectance).
            const double radius = std::sqrt(asset.samples[o].area / std::numbers::pi) * toMm;
            for (int c = 0; c < 3; ++c)
                sum[c] += dipoleDiskReflectance(radius, material.channel(c)) * irradiance[3 * o + c];
            for (int c = 0; c < 3; ++c) radiance[3 * j + c] = float(sum[c] / std::numbers::pi);
        }
    });
    return radiance;
}

}  // namespace opal
