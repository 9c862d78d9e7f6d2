#include "delegate/relight/reference_gather.h"

#include "schema/error.h"
#include "schema/scatter/dipole.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <numbers>
#include <string>

namespace opal {

namespace {

// R_d(r) of one channel with the r-independent terms computed once (docs/ARCHITECTURE.md#dipole):
// R_d(r) = alpha'/(4 pi) [z_r (sigma_tr + 1/d_r) e^{-sigma_tr d_r}/d_r^2
//                       + z_v (sigma_tr + 1/d_v) e^{-sigma_tr d_v}/d_v^2].
class Dipole {
public:
    explicit Dipole(const DipoleCoefficients& c) {
        const double sigmaTPrime = c.sigmaSPrime + c.sigmaA;
        const double fdr = fresnelDiffuseReflectance(c.eta);
        const double a = (1.0 + fdr) / (1.0 - fdr);
        scale_ = c.sigmaSPrime / sigmaTPrime / (4.0 * std::numbers::pi);
        sigmaTr_ = std::sqrt(3.0 * c.sigmaA * sigmaTPrime);
        zr_ = 1.0 / sigmaTPrime;
        zv_ = zr_ * (1.0 + 4.0 * a / 3.0);
    }
    double operator()(double r2) const { return scale_ * (pole(r2, zr_) + pole(r2, zv_)); }

private:
    double pole(double r2, double z) const {
        const double d2 = r2 + z * z, d = std::sqrt(d2);
        return z * (sigmaTr_ + 1.0 / d) * std::exp(-sigmaTr_ * d) / d2;
    }
    double scale_ = 0.0, sigmaTr_ = 0.0, zr_ = 0.0, zv_ = 0.0;
};

}  // namespace

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
    const Dipole profile[3] = {Dipole(material.channel(0)), Dipole(material.channel(1)), Dipole(material.channel(2))};
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
